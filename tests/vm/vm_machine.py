"""The virtual shop machine of the VM test: QEMU with a virtio-gpu display (a kernel DRM/KMS
driver), a USB tablet (an absolute pointer the guest kernel exposes through evdev), the serial
console for the guest's log, a second serial port with a root shell for the test, and QMP for
screenshots and input.

QMP: docs/interop/qmp-spec.rst in QEMU's tree (a greeting, qmp_capabilities, then one JSON
object per line; asynchronous events interleave with replies and are skipped here)."""

import json
import os
import re
import select
import socket
import subprocess
import time

import vm_image


class VmError(Exception):
    pass


def _connect_unix(path, deadline):
    while True:
        try:
            sock = socket.socket(socket.AF_UNIX, socket.SOCK_STREAM)
            sock.connect(path)
            return sock
        except OSError:
            sock.close()
            if time.monotonic() > deadline:
                raise VmError(f"cannot connect to {path}")
            time.sleep(0.2)


class Qmp:
    def __init__(self, path, timeout_s=30.0):
        self.sock = _connect_unix(path, time.monotonic() + timeout_s)
        self.file = self.sock.makefile("rw", encoding="utf-8")
        self._reply()  # the greeting
        self.execute("qmp_capabilities")

    def _reply(self):
        while True:
            line = self.file.readline()
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
        self.sock.close()


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

    def __init__(self, image_dir, work_dir, memory_mb=1536, cpus=2):
        self.work_dir = work_dir
        self.serial_log = os.path.join(work_dir, "serial.log")
        qmp_path = os.path.join(work_dir, "qmp.sock")
        shell_path = os.path.join(work_dir, "shell.sock")
        for path in (qmp_path, shell_path, self.serial_log):
            if os.path.exists(path):
                os.remove(path)
        kvm = os.access("/dev/kvm", os.R_OK | os.W_OK)
        self.accelerator = "kvm" if kvm else "tcg"
        # systemd.journald.forward_to_console: the guest's journal (the kiosk's log among it)
        # on the serial console, which QEMU writes to serial.log.
        append = ("root=/dev/vda rw console=ttyS0,115200 quiet loglevel=4 "
                  "systemd.show_status=0 systemd.journald.forward_to_console=1 "
                  "systemd.mask=serial-getty@ttyS0.service")
        command = [
            "qemu-system-x86_64",
            "-machine", f"q35,accel={self.accelerator}",
            "-cpu", "host" if kvm else "max",
            "-smp", str(cpus), "-m", str(memory_mb),
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
            self.qmp = Qmp(qmp_path)
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
