"""The virtual shop machine of the VM test: QEMU with a virtio-gpu display (a kernel DRM/KMS
driver), a USB tablet (an absolute pointer the guest kernel exposes through evdev), the serial
console for the guest's log, a second serial port with a root shell for the test, and QMP for
screenshots and input.

QMP: docs/interop/qmp-spec.rst in QEMU's tree (a greeting, qmp_capabilities, then one JSON
object per line; asynchronous events interleave with replies and are skipped here).

The accelerator and CPU model are chosen by starting QEMU with each in turn
(choose_accelerator): a /dev/kvm that opens says nothing about whether the host's hypervisor
accepts the CPU model, or runs the guest's kernel. Under a hypervisor that refuses
IA32_ARCH_CAPABILITIES (MSR 0x10a) to its guests, `-cpu host` and `-cpu max` abort in QEMU's
first register write; without that one feature the same host runs. Some KVMs run the firmware
but not a stock kernel (under a kvm-pvm host Debian's kernel prints nothing with any CPU
model): with the guest's kernel given, a candidate must also get it to print."""

import collections
import json
import os
import re
import select
import shutil
import signal
import socket
import subprocess
import tempfile
import time

import vm_image


class VmError(Exception):
    pass


class QemuMissing(VmError):
    """No QEMU to run at all: the machine cannot run the test, which is no failure of it."""


def _connect_unix(path, deadline, alive=None):
    """`alive`: a callable that says whether whoever should listen there still runs; waiting
    stops as soon as it does not."""
    while True:
        try:
            sock = socket.socket(socket.AF_UNIX, socket.SOCK_STREAM)
            sock.connect(path)
            return sock
        except OSError:
            sock.close()
            if alive is not None and not alive():
                raise VmError(f"nobody listens on {path}: the process exited")
            if time.monotonic() > deadline:
                raise VmError(f"cannot connect to {path}")
            time.sleep(0.1)


class Qmp:
    def __init__(self, path, timeout_s=30.0, reply_timeout_s=None, alive=None):
        self.sock = _connect_unix(path, time.monotonic() + timeout_s, alive)
        # A QEMU that accepts the connection and then says nothing is as good as one that never
        # started: every read has a limit.
        self.sock.settimeout(reply_timeout_s or timeout_s)
        self.file = self.sock.makefile("rw", encoding="utf-8")
        try:
            self._reply()  # the greeting
            self.execute("qmp_capabilities")
        except VmError:
            self.close()
            raise

    def _reply(self):
        while True:
            try:
                line = self.file.readline()
            except (socket.timeout, OSError) as error:
                raise VmError(f"QMP did not answer: {error or 'timed out'}")
            if not line:
                raise VmError("QMP connection closed")
            message = json.loads(line)
            if "event" not in message:
                return message

    def execute(self, command, **arguments):
        request = {"execute": command}
        if arguments:
            request["arguments"] = arguments
        self.file.write(json.dumps(request) + "\n")
        self.file.flush()
        reply = self._reply()
        if "error" in reply:
            raise VmError(f"QMP {command}: {reply['error'].get('desc', reply['error'])}")
        return reply.get("return")

    def screenshot(self, path):
        """The scanout as QEMU shows it (the guest's framebuffer on the display), as RGB."""
        if os.path.exists(path):
            os.remove(path)
        self.execute("screendump", filename=str(path))
        picture = vm_image.read(path)
        os.remove(path)  # a megabyte each; the checks write the ones they judge as PNG
        return picture

    def pointer(self, x, y, button=None):
        """Moves the tablet to (x, y) in [0, 1] of the screen; presses or releases the left
        button when `button` is True or False. The tablet's axes run 0..32767
        (hw/input/hid.c), and QMP's absolute values are in that range."""
        events = [
            {"type": "abs", "data": {"axis": "x", "value": round(x * 32767)}},
            {"type": "abs", "data": {"axis": "y", "value": round(y * 32767)}},
        ]
        if button is not None:
            events.append({"type": "btn", "data": {"down": button, "button": "left"}})
        self.execute("input-send-event", events=events)

    def close(self):
        try:
            self.file.close()  # flushes what is left of a request, to a QEMU that may be gone
        except OSError:
            pass
        self.sock.close()


Candidate = collections.namedtuple("Candidate", "accelerator cpu")

# In the order tried: the host's own CPU; the same without IA32_ARCH_CAPABILITIES (the MSR some
# hypervisors refuse to their guests, and QEMU aborts on); a plain 64-bit model, which asks the
# host for little; plain emulation.
CANDIDATES = (
    Candidate("kvm", "host"),
    Candidate("kvm", "host,-arch-capabilities"),
    Candidate("kvm", "qemu64"),
    Candidate("tcg", "max"),
)


def machine_arguments(candidate, cpus, memory_mb):
    """The part of QEMU's command line a probe and the real machine share."""
    return ["-machine", f"q35,accel={candidate.accelerator}", "-cpu", candidate.cpu,
            "-smp", str(cpus), "-m", str(memory_mb)]


class Choice:
    def __init__(self, candidate, passed_over):
        self.candidate = candidate
        self.accelerator = candidate.accelerator
        self.cpu = candidate.cpu
        self.passed_over = passed_over  # [(Candidate, reason)] in the order tried

    def describe(self):
        return f"{self.accelerator} with -cpu {self.cpu}"

    def report(self):
        """For the test's log: what it runs under, and why each candidate before was not."""
        return [f"QEMU runs under {self.describe()}"] + [
            f"passed over {c.accelerator} with -cpu {c.cpu}: {reason}"
            for c, reason in self.passed_over]


def qemu_version(qemu="qemu-system-x86_64"):
    """QEMU's first line of --version; QemuMissing when there is no `qemu` to run."""
    try:
        result = subprocess.run([qemu, "--version"], stdout=subprocess.PIPE,
                                stderr=subprocess.STDOUT, text=True, timeout=30)
    except FileNotFoundError as error:
        raise QemuMissing(f"cannot run {qemu}: {error}")
    except (OSError, subprocess.TimeoutExpired) as error:
        raise VmError(f"{qemu} --version: {error}")
    return (result.stdout.splitlines() or ["?"])[0]


def _exit_text(code):
    if code < 0:
        try:
            return f"killed by {signal.Signals(-code).name}"
        except ValueError:
            return f"killed by signal {-code}"
    return f"exited with status {code}"


# What the guest's kernel prints first (with console=ttyS0 and loglevel=7).
KERNEL_SIGN_OF_LIFE = "Linux version"


def probe(candidate, qemu="qemu-system-x86_64", cpus=2, memory_mb=1536, timeout_s=5.0,
          settle_s=1.0, kernel=None, kernel_timeout_s=30.0):
    """Starts QEMU with `candidate` and says why it is unusable, or None when it is: QMP must
    answer within `timeout_s`, report the machine running, and QEMU must still run `settle_s`
    later (KVM refuses a register when the CPUs first start, which may come after QMP is up).
    With `kernel` (the guest's), QEMU boots it with no disk and its first line must reach the
    serial port within `kernel_timeout_s`; without, the firmware runs and nothing more."""
    folder = tempfile.mkdtemp(prefix="gem-qemu-probe-")
    qmp_path = os.path.join(folder, "qmp.sock")
    log_path = os.path.join(folder, "qemu.log")
    serial_path = os.path.join(folder, "serial.log")
    command = [qemu] + machine_arguments(candidate, cpus, memory_mb) + [
        "-nodefaults", "-display", "none", "-no-reboot",
        "-qmp", f"unix:{qmp_path},server=on,wait=off"]
    if kernel:
        # No root: after its first lines the kernel panics and waits (panic=0), still running.
        command += ["-kernel", kernel, "-append", "console=ttyS0 loglevel=7 panic=0",
                    "-serial", f"file:{serial_path}"]

    def last_lines():
        try:
            with open(log_path, errors="replace") as f:
                lines = [line.strip() for line in f if line.strip()]
        except OSError:
            lines = []
        return " / ".join(lines[-3:]) or "no output"

    with open(log_path, "w") as log_file:
        try:
            process = subprocess.Popen(command, stdin=subprocess.DEVNULL, stdout=log_file,
                                       stderr=subprocess.STDOUT)
        except OSError as error:
            shutil.rmtree(folder, ignore_errors=True)
            if isinstance(error, FileNotFoundError):
                raise QemuMissing(f"cannot run {qemu}: {error}")
            return f"cannot run {qemu}: {error}"
    qmp = None
    try:
        try:
            qmp = Qmp(qmp_path, timeout_s=timeout_s, alive=lambda: process.poll() is None)
            status = qmp.execute("query-status")
        except VmError as error:
            if process.poll() is not None:
                return f"QEMU {_exit_text(process.returncode)}: {last_lines()}"
            return f"QMP did not answer in {timeout_s:g} s ({error})"
        if not status.get("running"):
            return f"QEMU started but its machine is {status.get('status', 'not running')}"
        time.sleep(settle_s)
        if process.poll() is not None:
            return f"QEMU {_exit_text(process.returncode)} after starting: {last_lines()}"
        if kernel:
            deadline = time.monotonic() + kernel_timeout_s
            while not _contains(serial_path, KERNEL_SIGN_OF_LIFE):
                if process.poll() is not None:
                    return (f"QEMU {_exit_text(process.returncode)} before the guest's kernel "
                            f"printed a line: {last_lines()}")
                if time.monotonic() > deadline:
                    return (f"QEMU runs, but the guest's kernel printed nothing in "
                            f"{kernel_timeout_s:g} s")
                time.sleep(0.2)
        return None
    finally:
        if qmp is not None:
            try:
                qmp.execute("quit")
            except (VmError, OSError):
                pass
            qmp.close()
        # One that never answered gets no time to quit on its own.
        if process.poll() is None:
            try:
                process.wait(timeout=2 if qmp is not None else 0)
            except subprocess.TimeoutExpired:
                process.kill()
                process.wait()
        shutil.rmtree(folder, ignore_errors=True)


def _contains(path, text):
    try:
        with open(path, errors="replace") as f:
            return text in f.read()
    except OSError:
        return False


def choose_accelerator(qemu="qemu-system-x86_64", accelerator="auto", cpus=2, memory_mb=1536,
                       timeout_s=5.0, settle_s=1.0, kernel=None, kernel_timeout_s=30.0):
    """The first of CANDIDATES (those of `accelerator` unless it is "auto") that QEMU runs;
    VmError, naming every candidate and why, when none does; QemuMissing when there is no
    `qemu` to run."""
    passed_over = []
    for candidate in CANDIDATES:
        if accelerator not in ("auto", candidate.accelerator):
            continue
        reason = probe(candidate, qemu, cpus, memory_mb, timeout_s, settle_s, kernel,
                       kernel_timeout_s)
        if reason is None:
            return Choice(candidate, passed_over)
        passed_over.append((candidate, reason))
    raise VmError("QEMU runs with none of the accelerators tried: " + "; ".join(
        f"{c.accelerator} -cpu {c.cpu}: {reason}" for c, reason in passed_over))


class GuestShell:
    """Commands for the root shell on the guest's second serial port
    (guest/vm-test-shell.sh): one line in, its output and "VM-TEST-DONE <status>" back."""

    DONE = re.compile(rb"VM-TEST-DONE (\d+)\n")

    def __init__(self, path, timeout_s):
        deadline = time.monotonic() + timeout_s
        self.sock = _connect_unix(path, deadline)
        self.buffer = b""
        # Characters the guest sent before anyone listened are gone: ask until it answers.
        while True:
            try:
                self.run("true", timeout_s=5.0)
                return
            except VmError:
                if time.monotonic() > deadline:
                    raise VmError("the guest's test shell never answered")

    def run(self, command, timeout_s=60.0, check=True):
        self.buffer = b""
        self.sock.sendall(command.encode() + b"\n")
        deadline = time.monotonic() + timeout_s
        while True:
            match = self.DONE.search(self.buffer)
            if match:
                output = self.buffer[: match.start()].decode(errors="replace")
                self.buffer = self.buffer[match.end() :]
                status = int(match.group(1))
                if check and status != 0:
                    raise VmError(f"guest: `{command}` exited {status}: {output.strip()}")
                return output
            left = deadline - time.monotonic()
            if left <= 0:
                raise VmError(f"guest: `{command}` did not finish in {timeout_s:.0f} s")
            ready, _, _ = select.select([self.sock], [], [], left)
            if ready:
                chunk = self.sock.recv(65536)
                if not chunk:
                    raise VmError("the guest's test shell closed")
                self.buffer += chunk

    def close(self):
        self.sock.close()


class Machine:
    """One boot of the image; the disk is a snapshot, so every boot starts from the image."""

    def __init__(self, image_dir, work_dir, choice, memory_mb=1536, cpus=2,
                 qemu="qemu-system-x86_64"):
        self.work_dir = work_dir
        self.serial_log = os.path.join(work_dir, "serial.log")
        qmp_path = os.path.join(work_dir, "qmp.sock")
        shell_path = os.path.join(work_dir, "shell.sock")
        for path in (qmp_path, shell_path, self.serial_log):
            if os.path.exists(path):
                os.remove(path)
        self.accelerator = choice.accelerator
        self.cpu = choice.cpu
        # systemd.journald.forward_to_console: the guest's journal (the kiosk's log among it)
        # on the serial console, which QEMU writes to serial.log.
        append = ("root=/dev/vda rw console=ttyS0,115200 quiet loglevel=4 "
                  "systemd.show_status=0 systemd.journald.forward_to_console=1 "
                  "systemd.mask=serial-getty@ttyS0.service")
        # Under plain emulation a frame takes seconds: the guest raises the kiosk's WatchdogSec
        # (guest/vm-test-watchdog-generator). Under KVM it runs the shipped unit.
        self.relaxed_watchdog = choice.accelerator != "kvm"
        if self.relaxed_watchdog:
            append += " gemkiosk_vm.watchdog=relaxed"
        command = [
            qemu, *machine_arguments(choice.candidate, cpus, memory_mb),
            "-kernel", os.path.join(image_dir, "vmlinuz"),
            "-initrd", os.path.join(image_dir, "initrd.img"),
            "-append", append,
            "-drive", f"file={os.path.join(image_dir, 'root.img')},if=virtio,format=raw,snapshot=on",
            # virtio-gpu: a KMS driver with a render node; Mesa draws with llvmpipe through it
            # (kms_swrast). QEMU's standard VGA (bochs-drm) failed its mode set here.
            "-device", "virtio-gpu-pci,xres=1024,yres=768", "-vga", "none",
            "-device", "qemu-xhci", "-device", "usb-tablet",
            "-serial", f"file:{self.serial_log}",
            "-serial", f"unix:{shell_path},server=on,wait=off",
            "-qmp", f"unix:{qmp_path},server=on,wait=off",
            "-display", "none", "-nic", "none", "-no-reboot",
        ]
        self.started = time.monotonic()
        self.process = subprocess.Popen(command, stdin=subprocess.DEVNULL,
                                        stdout=open(os.path.join(work_dir, "qemu.log"), "w"),
                                        stderr=subprocess.STDOUT)
        try:
            # Replies wait for an emulated machine that may be slow under load.
            self.qmp = Qmp(qmp_path, timeout_s=30.0, reply_timeout_s=300.0,
                           alive=lambda: self.process.poll() is None)
        except VmError:
            self.stop()
            raise VmError("QEMU did not start: " + self.qemu_log())
        self.shell_path = shell_path
        self.shell = None

    def connect_shell(self, timeout_s):
        self.shell = GuestShell(self.shell_path, timeout_s)
        return self.shell

    def qemu_log(self):
        with open(os.path.join(self.work_dir, "qemu.log"), errors="replace") as f:
            return f.read()[-2000:]

    def serial_tail(self, lines=60):
        try:
            with open(self.serial_log, errors="replace") as f:
                return "".join(f.readlines()[-lines:])
        except OSError:
            return ""

    def stop(self):
        if self.process.poll() is None:
            try:
                self.qmp.execute("quit")
            except Exception:
                pass
            try:
                self.process.wait(timeout=10)
            except subprocess.TimeoutExpired:
                self.process.kill()
                self.process.wait()
