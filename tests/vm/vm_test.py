#!/usr/bin/env python3
"""The kiosk on a virtual shop machine, end to end: a real kernel's DRM/KMS driver and evdev
devices, systemd starting the packaged service with its user, logind session and sandbox.

  vm_test.py --build-dir BUILD --source-dir SRC --work-dir DIR --gemkiosk PROGRAM
             --gemtables PROGRAM [--short] [--accel auto|kvm|tcg]

Builds the Debian package (cpack), small catalogues signed with a test chain's minisign key,
and the chain's apt repository of two catalogue packages (gemtables package, reprepro), makes the guest's disk
(image.sh), boots it under QEMU and checks, from the host:
  always:  the service reports ready (first frame on screen); the screen shows the stone as the
           kiosk draws it headless on the host from the same config and catalogue; a drag with
           the virtual tablet turns it, to the view the host's kiosk reaches replaying what the
           guest's kernel delivered (evemu-record in the guest);
  not with --short: a catalogue staff copy into the inbox is shown; after SIGKILL systemd
           starts the kiosk again and the screen comes back; a damaged catalogue is refused,
           set aside as NAME.rejected, the old one stays on screen; under KVM, where the guest runs
           the shipped unit as it is, a kiosk whose frames stop (SIGSTOP) is restarted by
           systemd's watchdog; the legacy modesetting path (display.atomic = false) shows the
           same picture; before those two, a catalogue signed with an unknown key is refused,
           and the chain's signed apt repository (reprepro) installs a catalogue package, which
           is shown, and then upgrades it.
Every run ends with a clean stop and prints one "figures:" line: the accelerator, boot to the
first frame, the frame rate in the guest, the restarts' times and the whole scenario's.
Exits 0 on success, 1 on a failed check, 77 when this machine cannot run virtual machines or
build the image (CTest's SKIP_RETURN_CODE)."""

import argparse
import glob
import os
import re
import shutil
import subprocess
import sys
import time

# The helpers beside this file; no byte-code written into the source tree.
sys.dont_write_bytecode = True
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import vm_image  # noqa: E402
from vm_machine import (Machine, QemuMissing, VmError, choose_accelerator,  # noqa: E402
                        qemu_version)

SKIP = 77
HERE = os.path.dirname(os.path.abspath(__file__))
# Whole-picture PSNR (8-bit) above which two pictures count as the same: the guest and the host
# draw with the same Mesa (llvmpipe) on different CPUs, so they may differ in the last bit.
SAME_DB = 35.0
# A stone the size it is on this screen changes the picture by more than this much.
MARGIN_DB = 5.0
FIRST_STONE = "oval-sapphire"
NEW_STONE = "tolkowsky-diamond"
# A catalogue of one design (a stone description, no database), shown with the exact method.
DESIGN_STONE = "marquise-garnet"
DESIGN_CATALOGUE = "designs"
# The chain's catalogue package and what its two versions hold: (catalogue name, design, ring).
# The melee diamond is too small for the parametric ring's claws: a loose stone.
CHAIN_PACKAGE = "gemkiosk-catalogue-chain"
CHAIN_VERSIONS = {1: ("chain-spring", "emerald-cut-emerald", "parametric"),
                  2: ("chain-summer", "melee-diamond", "none")}


class CheckFailed(Exception):
    pass


def log(text):
    print(f"[vm {time.strftime('%H:%M:%S')}] {text}", flush=True)


def run(command, **kwargs):
    return subprocess.run(command, check=True, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                          text=True, **kwargs)


class Host:
    """What the host builds and draws: the package, the catalogues, the reference pictures."""

    def __init__(self, args):
        self.args = args
        self.work = args.work_dir
        self.gemkiosk = args.gemkiosk
        self.gemtables = args.gemtables
        self.config = os.path.join(HERE, "guest", "gemkiosk.toml")

    def package(self):
        out = os.path.join(self.work, "deb")
        shutil.rmtree(out, ignore_errors=True)
        # -B keeps CPack's staging out of the build folder, where the package test runs its own.
        run(["cpack", "--config", os.path.join(self.args.build_dir, "CPackConfig.cmake"),
             "-G", "DEB", "-B", out])
        debs = glob.glob(os.path.join(out, "*.deb"))
        if len(debs) != 1:
            raise CheckFailed(f"cpack made {len(debs)} packages in {out}")
        return debs[0]

    def keys(self):
        """The chain's minisign key, which the guest's kiosk trusts, and a stranger's."""
        keys = os.path.join(self.work, "keys")
        os.makedirs(keys, exist_ok=True)
        for name in ("chain", "stranger"):
            run(["minisign", "-G", "-W", "-f", "-p", os.path.join(keys, name + ".pub"),
                 "-s", os.path.join(keys, name + ".key")])
        return keys

    def seal(self, directory, key):
        run([self.gemtables, "seal", directory, "--sign", key])

    def catalogues(self, keys):
        """first: the sapphire the kiosk starts with (the shipped default, not signed);
        diamond: staff's new catalogue. Small databases (64 and 128 px, 10°): the stone is
        about 100 px tall on this screen. designs: a garnet's stone description only, no
        tables. Both signed with the chain's key; stranger: the designs signed with another."""
        root = os.path.join(self.work, "catalogues")
        for folder, stone in (("first", FIRST_STONE), ("diamond", NEW_STONE)):
            directory = os.path.join(root, folder)
            database = os.path.join(directory, stone + ".gemdb")
            os.makedirs(directory, exist_ok=True)
            if not os.path.exists(database):
                run([self.gemtables, "build",
                     os.path.join(self.args.source_dir, "config", "stones", stone + ".toml"),
                     "-o", database, "--levels", "64,128", "--spacing", "10", "--depth", "6"])
            with open(os.path.join(directory, "catalogue.toml"), "w") as f:
                f.write(f'[catalogue]\nname = "{stone}"\n\n[[stone]]\nname = "{stone}"\n'
                        f'database = "{stone}.gemdb"\nring = "parametric"\n')
        designs = os.path.join(root, DESIGN_CATALOGUE)
        os.makedirs(designs, exist_ok=True)
        shutil.copy(os.path.join(self.args.source_dir, "config", "stones", DESIGN_STONE + ".toml"),
                    designs)
        with open(os.path.join(designs, "catalogue.toml"), "w") as f:
            f.write(f'[catalogue]\nname = "{DESIGN_CATALOGUE}"\n\n[[stone]]\n'
                    f'name = "{DESIGN_STONE}"\ndesign = "{DESIGN_STONE}.toml"\n'
                    f'ring = "parametric"\n')
        stranger = os.path.join(root, "stranger")
        shutil.rmtree(stranger, ignore_errors=True)
        shutil.copytree(designs, stranger)
        for directory in (os.path.join(root, "diamond"), designs):
            self.seal(directory, os.path.join(keys, "chain.key"))
        self.seal(stranger, os.path.join(keys, "stranger.key"))
        return root

    def chain_catalogue(self, version):
        """The catalogue of the chain's package version 1 or 2: one design each."""
        name, stone, ring = CHAIN_VERSIONS[version]
        directory = os.path.join(self.work, "chain", str(version))
        shutil.rmtree(directory, ignore_errors=True)
        os.makedirs(directory)
        shutil.copy(os.path.join(self.args.source_dir, "config", "stones", stone + ".toml"),
                    directory)
        with open(os.path.join(directory, "catalogue.toml"), "w") as f:
            f.write(f'[catalogue]\nname = "{name}"\n\n[[stone]]\nname = "{stone}"\n'
                    f'design = "{stone}.toml"\nring = "{ring}"\n')
        return directory

    def repository(self, keys):
        """The chain's apt repository as reprepro makes it, signed with a GnuPG key of its
        own, in two states: v1 publishes version 1 of the catalogue package, v2 version 2.
        Returns the folder for the guest: v1/, v2/ (dists and pool), chain-archive.gpg (the
        repository's public key) and chain.pub (the catalogues' key)."""
        out = os.path.join(self.work, "repo")
        shutil.rmtree(out, ignore_errors=True)
        gnupg = os.path.join(self.work, "gnupg")
        shutil.rmtree(gnupg, ignore_errors=True)
        os.makedirs(gnupg, mode=0o700)
        env = dict(os.environ, GNUPGHOME=gnupg)
        run(["gpg", "--batch", "--passphrase", "", "--quick-gen-key",
             "gemkiosk test chain <chain@example.org>", "ed25519", "sign", "never"], env=env)
        listing = run(["gpg", "--batch", "--with-colons", "--list-keys"], env=env).stdout
        fingerprint = next(line.split(":")[9] for line in listing.splitlines()
                           if line.startswith("fpr:"))
        debs = os.path.join(self.work, "chain-debs")
        shutil.rmtree(debs, ignore_errors=True)
        os.makedirs(debs)
        build = os.path.join(self.work, "reprepro")
        shutil.rmtree(build, ignore_errors=True)
        os.makedirs(os.path.join(build, "conf"))
        with open(os.path.join(build, "conf", "distributions"), "w") as f:
            f.write("Origin: gemkiosk-test-chain\nLabel: gemkiosk-test-chain\n"
                    "Codename: bookworm\nArchitectures: amd64\nComponents: main\n"
                    f"Description: the test chain's catalogues\nSignWith: {fingerprint}\n")
        for version in (1, 2):
            catalogue = self.chain_catalogue(version)
            self.seal(catalogue, os.path.join(keys, "chain.key"))
            run([self.gemtables, "package", catalogue, "--version", str(version),
                 "--package", CHAIN_PACKAGE, "-o", debs])
            deb = os.path.join(debs, f"{CHAIN_PACKAGE}_{version}_all.deb")
            run(["reprepro", "-b", build, "includedeb", "bookworm", deb], env=env)
            for part in ("dists", "pool"):
                shutil.copytree(os.path.join(build, part), os.path.join(out, f"v{version}", part))
        with open(os.path.join(out, "chain-archive.gpg"), "wb") as f:
            f.write(subprocess.run(["gpg", "--batch", "--export", fingerprint], env=env,
                                   check=True, stdout=subprocess.PIPE).stdout)
        subprocess.run(["gpgconf", "--kill", "gpg-agent"], env=env, check=False)
        shutil.copy(os.path.join(keys, "chain.pub"), out)
        return out

    def picture(self, name, catalogue, replay=None):
        """The guest's config drawn headless on the host: the start view, or the view a replay
        of `replay` (an evemu recording) ends at."""
        out = os.path.join(self.work, "host", name)
        shutil.rmtree(out, ignore_errors=True)
        os.makedirs(out)
        command = [self.gemkiosk, "--config", self.config, "--backend", "headless",
                   "--catalogue", catalogue, "--state-dir", os.path.join(out, "state"),
                   "--snapshot-dir", out, "--snapshot-last", "--seconds", "120"]
        command += ["--replay", replay, "--exit-after-replay"] if replay else ["--frames", "3"]
        result = subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                                text=True)
        snapshot = os.path.join(out, "last.png")
        if result.returncode != 0 or not os.path.exists(snapshot):
            raise CheckFailed(f"the host's kiosk could not draw {name}:\n{result.stdout[-3000:]}")
        return vm_image.read(snapshot)


class Guest:
    def __init__(self, machine, shell, work):
        self.machine = machine
        self.shell = shell
        self.work = work
        self.shots = 0

    def unit(self, *properties):
        # `systemctl show` prints every property asked for, an empty one as "Name=". Once (1 run
        # of 2) its answer over the serial shell lacked one right after the unit went active:
        # asked again.
        for _ in range(3):
            text = self.shell.run("systemctl show gemkiosk.service -p " + ",".join(properties))
            values = dict(line.split("=", 1) for line in text.splitlines() if "=" in line)
            if all(p in values for p in properties):
                break
            time.sleep(1)
        return [values.get(p, "") for p in properties]

    def wait_active(self, timeout_s, restarts=None):
        """Until the kiosk has its first frame on screen: systemd calls it active (READY=1,
        Type=notify) with the status "showing ..." (without a display it is ready too, with
        "waiting for a display"). With `restarts`, after that many restarts."""
        deadline = time.monotonic() + timeout_s
        while True:
            state, sub, count, status = self.unit("ActiveState", "SubState", "NRestarts",
                                                  "StatusText")
            if (state == "active" and status.startswith("showing") and
                    (restarts is None or int(count or 0) >= restarts)):
                return
            if state == "failed":
                raise CheckFailed("gemkiosk.service failed:\n" + self.journal())
            if time.monotonic() > deadline:
                raise CheckFailed(f"gemkiosk.service still {state}/{sub} ({status}) after "
                                  f"{timeout_s} s:\n" + self.journal())
            time.sleep(2)

    # The kiosk's own lines carry SYSLOG_IDENTIFIER=gemkiosk; their unit is the logind
    # session's scope (session-N.scope), where its PAM session moves it, not gemkiosk.service.
    def journal(self, lines=40):
        return self.shell.run(f"journalctl -b -t gemkiosk -o cat --no-pager -n {lines}",
                              check=False)

    def wait_for_log(self, pattern, timeout_s, since=None):
        """The first line of the kiosk's journal (this boot, or from the guest's clock time
        `since`, in seconds) matching `pattern`."""
        deadline = time.monotonic() + timeout_s
        window = f"--since @{since}" if since else "-b"
        while True:
            text = self.shell.run(f"journalctl {window} -t gemkiosk -o cat --no-pager",
                                  check=False)
            for line in text.splitlines():
                if re.search(pattern, line):
                    return line
            if time.monotonic() > deadline:
                raise CheckFailed(f"no line matching '{pattern}' in the kiosk's journal after "
                                  f"{timeout_s} s:\n" + "\n".join(text.splitlines()[-30:]))
            time.sleep(2)

    def active_since_s(self):
        """The guest's clock when the kiosk last became ready, its first frame on screen."""
        active_us, = self.unit("ActiveEnterTimestampMonotonic")
        return int(active_us) / 1e6

    def screenshot(self, name):
        self.shots += 1
        return self.machine.qmp.screenshot(os.path.join(self.work, f"shot-{self.shots}-{name}.ppm"))

    def wait_for_picture(self, name, expected, others, timeout_s):
        """Screenshots until one matches `expected`; then it must also be clearly further from
        each of `others`. Under emulation a frame takes seconds, so the screen gets there in
        its own time."""
        deadline = time.monotonic() + timeout_s
        best = None
        while True:
            shot = self.screenshot(name)
            if shot.size == expected.size:
                value = vm_image.psnr(shot, expected)
                if best is None or value > best[0]:
                    best = (value, shot)
                if value >= SAME_DB:
                    break
            elif best is None:
                best = (0.0, shot)
            if time.monotonic() > deadline:
                shot = best[1]
                break
            time.sleep(1.0)
        compare(name, shot, expected, others, self.work)
        return shot


def compare(name, shot, expected, others, work):
    """The screenshot must match `expected` and be clearly further from each of `others`."""
    shot.save(os.path.join(work, name + "-screen.png"))
    if shot.size != expected.size:
        raise CheckFailed(f"{name}: the screen is {shot.size}, expected {expected.size}")
    matched = vm_image.psnr(shot, expected)
    against = {label: vm_image.psnr(shot, picture) for label, picture in others.items()}
    vm_image.side_by_side([shot, expected]).save(os.path.join(work, name + ".png"))
    detail = ", ".join(f"{v:.1f} dB to {k}" for k, v in against.items())
    log(f"{name}: {matched:.1f} dB to the expected picture; {detail}")
    if matched < SAME_DB:
        raise CheckFailed(f"{name}: {matched:.1f} dB to the expected picture (need {SAME_DB})")
    for label, value in against.items():
        if value > matched - MARGIN_DB:
            raise CheckFailed(f"{name}: {value:.1f} dB to {label}, too close to the "
                              f"{matched:.1f} dB to the expected picture")


def drag(guest, qmp, work):
    """A one-finger drag to the right across the middle of the screen with the USB tablet, held
    still before lifting; the guest records what its kernel delivers."""
    device = guest.shell.run(
        "for d in /sys/class/input/event*; do grep -q 'QEMU USB Tablet' $d/device/name && "
        "echo /dev/input/${d##*/}; done; true").strip().splitlines()
    if len(device) != 1:
        raise CheckFailed(f"the guest has {len(device)} USB tablets: {device}")
    description = guest.shell.run(f"evemu-describe {device[0]}")
    with open(os.path.join(work, "qemu-usb-tablet.desc"), "w") as f:
        f.write(description)
    guest.shell.run(f"setsid sh -c 'echo $$ > /run/evemu.pid; "
                    f"exec evemu-record {device[0]} > /run/drag.evemu' </dev/null >/dev/null 2>&1 &")
    time.sleep(2.0)
    qmp.pointer(0.35, 0.5)
    time.sleep(0.3)
    qmp.pointer(0.35, 0.5, button=True)
    for step in range(1, 11):
        time.sleep(0.1)
        qmp.pointer(0.35 + 0.03 * step, 0.5)
    time.sleep(0.5)
    qmp.pointer(0.65, 0.5, button=False)
    time.sleep(2.0)
    # evemu-record writes through stdio: SIGINT ends it and flushes what it recorded.
    guest.shell.run("kill -INT $(cat /run/evemu.pid); sleep 1")
    recording = guest.shell.run("cat /run/drag.evemu")
    path = os.path.join(work, "drag.evemu")
    with open(path, "w") as f:
        f.write(recording)
    if "E:" not in recording:
        raise CheckFailed("the guest's kernel delivered no tablet events:\n" + recording[-2000:])
    return path


def no_warnings(guest, since, what):
    """No line of priority warning or worse from the kiosk since the guest's time `since`."""
    complaints = guest.shell.run(f"journalctl -t gemkiosk -p warning -o cat --no-pager "
                                 f"--since @{since}").strip()
    if complaints and "-- No entries --" not in complaints:
        raise CheckFailed(f"warnings from the kiosk over {what}:\n" + complaints)


def vt_switch(number):
    """A shell command that switches the guest's console to VT `number` and waits for it: the
    VT_ACTIVATE and VT_WAITACTIVE ioctls (linux/vt.h: 0x5606, 0x5607), through perl, which
    every Debian system has (perl-base is essential)."""
    return ("timeout 90 perl -e 'open(my $t, \"+<\", \"/dev/tty0\") or die \"tty0: $!\"; "
            f"ioctl($t, 0x5606, {number}) or die \"VT_ACTIVATE: $!\"; "
            f"ioctl($t, 0x5607, {number}) or die \"VT_WAITACTIVE: $!\";'")


def frame_rate(summary):
    """frames/s from the kiosk's "frames: N frames in S s: R frames/s; ..." line."""
    match = re.search(r"frames: \d+ frames in [\d.]+ s: ([\d.]+) frames/s", summary)
    if not match:
        raise CheckFailed(f"no frame rate in the kiosk's summary: {summary}")
    return float(match.group(1))


def shipped_watchdog(source_dir):
    """WatchdogSec= of the unit the package ships, as systemctl shows it ("10s")."""
    with open(os.path.join(source_dir, "systemd", "gemkiosk.service")) as f:
        match = re.search(r"^WatchdogSec=(\S+)$", f.read(), re.M)
    if not match:
        raise CheckFailed("systemd/gemkiosk.service sets no WatchdogSec=")
    return match.group(1)


def watchdog(args, guest, choice, figures, expected, others):
    """Under KVM: the guest runs the unit as shipped, and a kiosk whose frames stop is
    restarted by systemd's watchdog. Returns the restarts it made (0 when skipped)."""
    shipped = shipped_watchdog(args.source_dir)
    limit, drop_ins = guest.unit("WatchdogUSec", "DropInPaths")
    if guest.machine.relaxed_watchdog:
        if "vm-watchdog.conf" not in drop_ins:
            raise CheckFailed(f"under {choice.describe()} the guest should raise WatchdogSec with "
                              f"its drop-in; it has WatchdogSec={limit}, drop-ins '{drop_ins}'")
        log(f"watchdog step skipped: under {choice.describe()} a frame takes seconds, so the "
            f"guest runs WatchdogSec={limit} (tests/vm/guest/gemkiosk-watchdog.conf) instead of "
            f"the shipped {shipped}; the watchdog is exercised under KVM only")
        return 0
    if drop_ins.strip() or limit != shipped:
        raise CheckFailed(f"under KVM the guest should run the shipped unit (WatchdogSec="
                          f"{shipped}, no drop-in); it has WatchdogSec={limit}, drop-ins "
                          f"'{drop_ins}'")
    pid, restarts = guest.unit("MainPID", "NRestarts")
    since = int(guest.shell.run("date +%s").strip()) - 1
    # SIGSTOP: the kiosk's frames stop as a hung GPU or a lost page flip would stop them, and it
    # sends no pings. systemd's own SIGCONT after its SIGABRT resumes it just to die. The
    # guest's /proc/uptime is the clock of systemd's *TimestampMonotonic (never suspended).
    stopped_at = float(guest.shell.run(f"kill -STOP {pid} && cat /proc/uptime").split()[0])
    log(f"stopped the kiosk (pid {pid}) with SIGSTOP; the shipped WatchdogSec={shipped} is "
        "to act")
    try:
        guest.wait_active(timeout_s=120, restarts=int(restarts) + 1)
    except CheckFailed:
        guest.shell.run(f"kill -CONT {pid}", check=False)
        raise
    new_pid, = guest.unit("MainPID")
    if new_pid == pid:
        raise CheckFailed("the kiosk's pid did not change after its watchdog ran out")
    figures["watchdog_restart_s"] = guest.active_since_s() - stopped_at
    lines = guest.shell.run(f"journalctl -u gemkiosk.service --since @{since} "
                            "-o short-monotonic --no-pager", check=False).splitlines()
    fired = [line for line in lines if "Watchdog timeout" in line]
    if not fired or not any("Failed with result 'watchdog'" in line for line in lines):
        raise CheckFailed("systemd's journal does not say the watchdog restarted the kiosk:\n" +
                          "\n".join(lines[-20:]))
    figures["watchdog_fired_s"] = float(fired[0].split("]")[0].strip("[ ")) - stopped_at
    log(f"systemd: {fired[0].split(': ', 1)[-1]} {figures['watchdog_fired_s']:.1f} s after "
        f"SIGSTOP; pid {new_pid} on screen {figures['watchdog_restart_s']:.1f} s after it")
    guest.wait_for_picture("watchdog-restart", expected, others, timeout_s=120)
    return 1


def legacy(guest, figures, expected, others):
    """display.atomic = false: the kiosk sets its mode and flips with the legacy calls, and the
    screen shows the same picture. The atomic kiosk's frame summary comes with its stop."""
    since = guest.shell.run("date +%s").strip()
    guest.shell.run("sed -i 's/^atomic = true$/atomic = false/' /etc/gemkiosk/gemkiosk.toml && "
                    "grep -qx 'atomic = false' /etc/gemkiosk/gemkiosk.toml")
    guest.shell.run("systemctl restart gemkiosk.service", timeout_s=300)
    guest.wait_active(timeout_s=300)
    summary = guest.wait_for_log(r"frames: \d+ frames in", timeout_s=30, since=since)
    log(f"kiosk in the guest, atomic: {summary}")
    figures["frames_per_s"] = frame_rate(summary)
    line = guest.wait_for_log(r"display: DRM .* lit", timeout_s=30, since=since)
    log(f"with atomic = false the kiosk says: {line}")
    if not line.endswith(" legacy lit"):
        raise CheckFailed(f"with display.atomic = false the kiosk did not use legacy KMS: {line}")
    guest.wait_for_picture("legacy", expected, others, timeout_s=180)
    no_warnings(guest, since, "a restart on the legacy modesetting path")


def config_checked_before_start(guest):
    """The unit ran `gemkiosk --check-config` on the kiosk's config (ExecStartPre=) before the
    kiosk itself: its verdict comes before the kiosk's first frame in the journal."""
    lines = guest.shell.run("journalctl -b -t gemkiosk -o cat --no-pager",
                            check=False).splitlines()
    verdict = "/etc/gemkiosk/gemkiosk.toml: no problems"
    checked = [i for i, line in enumerate(lines) if line == verdict]
    started = [i for i, line in enumerate(lines) if "first frame on screen" in line]
    if not checked or not started or checked[0] > started[0]:
        raise CheckFailed(f"no '{verdict}' before the kiosk's first frame:\n" +
                          "\n".join(lines[:30]))
    log("the config was checked before the kiosk started: " + verdict)


def scenario(args, host, guest, catalogues, figures, choice):
    first_catalogue = os.path.join(catalogues, "first")
    diamond_catalogue = os.path.join(catalogues, "diamond")
    empty = os.path.join(args.work_dir, "no-catalogue")
    os.makedirs(empty, exist_ok=True)

    log("waiting for gemkiosk.service to report its first frame")
    guest.wait_active(timeout_s=600)
    active_us, start_us = guest.unit("ActiveEnterTimestampMonotonic",
                                     "ExecMainStartTimestampMonotonic")
    figures["boot_to_first_frame_s"] = int(active_us) / 1e6
    figures["start_to_first_frame_s"] = (int(active_us) - int(start_us)) / 1e6
    log(f"first frame {figures['boot_to_first_frame_s']:.1f} s after the guest's kernel started "
        f"({figures['start_to_first_frame_s']:.1f} s after the kiosk did)")
    config_checked_before_start(guest)
    line = guest.wait_for_log(r"display: DRM .* lit", timeout_s=10)
    log("the kiosk says: " + line)
    # virtio-gpu does atomic modesetting: the default takes it (the legacy path comes later).
    if not line.endswith(" atomic lit"):
        raise CheckFailed(f"virtio-gpu offers atomic modesetting, the kiosk did not take it: {line}")

    # The stone is on screen: the guest's picture is the host's, and not the background alone.
    sapphire_start = host.picture("sapphire-start", first_catalogue)
    background = host.picture("background", empty)
    start = guest.wait_for_picture("first-frame", sapphire_start,
                                   {"the background alone": background}, timeout_s=180)

    # A drag turns it, as far as the same events turn the host's kiosk.
    recording = drag(guest, guest.machine.qmp, args.work_dir)
    sapphire_turned = host.picture("sapphire-turned", first_catalogue, replay=recording)
    turned = guest.wait_for_picture("drag", sapphire_turned, {"the view before the drag": start},
                                    timeout_s=180)
    if args.short:
        return

    # A second tablet plugged in and pulled out while the kiosk runs: the kiosk finds it in
    # /dev/input (inotify), opens it through the seat, and lets it go, without a warning.
    since = guest.shell.run("date +%s").strip()
    guest.machine.qmp.execute("device_add", driver="usb-tablet", id="second-tablet")
    line = guest.wait_for_log(r"input device \S+ \(QEMU QEMU USB Tablet\): absolute pointer",
                              timeout_s=120, since=since)
    path = line.split()[3]
    log(f"plugged in a second tablet: {line}")
    guest.machine.qmp.execute("device_del", id="second-tablet")
    log("pulled it out: " + guest.wait_for_log(f"input device {re.escape(path)} removed",
                                               timeout_s=120, since=since))
    no_warnings(guest, since, "a tablet plugged in and out")

    # Staff copy a new catalogue into the inbox; the kiosk validates it and shows it, keeping
    # the view the shopper left.
    guest.shell.run("runuser -u clerk -- cp -r /srv/vm-test/catalogues/diamond "
                    "/var/lib/gemkiosk/inbox/spring")
    guest.wait_for_log(f"showing catalogue '{NEW_STONE}'", timeout_s=180)
    diamond_turned = host.picture("diamond-turned", diamond_catalogue, replay=recording)
    diamond = guest.wait_for_picture("new-catalogue", diamond_turned, {"the sapphire": turned},
                                     timeout_s=180)

    # The kiosk is killed; systemd starts it again, on the catalogue it had installed.
    pid, restarts = guest.unit("MainPID", "NRestarts")
    if restarts != "0":
        raise CheckFailed(f"systemd restarted the kiosk {restarts} times before the test did:\n" +
                          guest.shell.run("journalctl -u gemkiosk.service -b -o cat --no-pager",
                                          check=False))
    killed_at = float(guest.shell.run(f"kill -KILL {pid} && cat /proc/uptime").split()[0])
    log(f"killed the kiosk (pid {pid}) with SIGKILL")
    guest.wait_active(timeout_s=300, restarts=1)
    new_pid, restarts = guest.unit("MainPID", "NRestarts")
    figures["restart_s"] = guest.active_since_s() - killed_at
    log(f"systemd restarted it as pid {new_pid} (NRestarts={restarts}); on screen "
        f"{figures['restart_s']:.1f} s after SIGKILL")
    if new_pid == pid:
        raise CheckFailed("the kiosk's pid did not change after SIGKILL")
    diamond_start = host.picture("diamond-start", diamond_catalogue)
    guest.wait_for_picture("restart", diamond_start,
                           {"the sapphire": sapphire_start, "the view before the restart": diamond},
                           timeout_s=180)

    # A keyboard plugged into the kiosk cannot switch it away: the kiosk grabs keyboards, so
    # Ctrl+Alt+F2 never reaches the console.
    guest.machine.qmp.execute("send-key", keys=[{"type": "qcode", "data": k}
                                                for k in ("ctrl", "alt", "f2")])
    time.sleep(3)
    active_vt = guest.shell.run("cat /sys/class/tty/tty0/active").strip()
    if active_vt != "tty1":
        raise CheckFailed(f"Ctrl+Alt+F2 on the kiosk's keyboard switched the console to {active_vt}")
    log("Ctrl+Alt+F2 on the keyboard: the console stays on tty1")

    # A VT switch by the system (as root): the kiosk gives the display up and takes it back,
    # with nothing worse than an info line in its log.
    since = guest.shell.run("date +%s").strip()
    guest.shell.run(vt_switch(2), timeout_s=120)
    guest.wait_for_log(r"seat: .* disabled", timeout_s=60)
    away = guest.screenshot("vt2")
    away.save(os.path.join(args.work_dir, "vt2-console.png"))
    if away.size == diamond_start.size and vm_image.psnr(away, diamond_start) >= SAME_DB:
        raise CheckFailed("after switching to tty2 the screen still shows the kiosk")
    log(f"switched to tty2: the screen shows the console ({away.width}x{away.height})")
    guest.shell.run(vt_switch(1), timeout_s=120)
    guest.wait_for_picture("vt-back", diamond_start, {"the sapphire": sapphire_start},
                           timeout_s=180)
    no_warnings(guest, since, "a VT switch")

    # A damaged copy (one byte flipped inside a view) is refused; the diamond stays.
    guest.shell.run(
        "rm -rf /tmp/bad && cp -r /srv/vm-test/catalogues/diamond /tmp/bad && "
        f"f=/tmp/bad/{NEW_STONE}.gemdb && half=$(( $(stat -c %s $f) / 2 )) && "
        "printf '\\132' | dd of=$f bs=1 seek=$half conv=notrunc status=none && "
        "chmod -R a+rX /tmp/bad && runuser -u clerk -- cp -r /tmp/bad /var/lib/gemkiosk/inbox/summer")
    line = guest.wait_for_log("rejected", timeout_s=180)
    log(f"the kiosk says: {line}")
    # The signed digest finds the flipped byte before the database's own checksums would.
    if NEW_STONE + ".gemdb" not in line or "digest" not in line:
        raise CheckFailed(f"the refusal does not name the database and the fault: {line}")
    # The clerk's copy is theirs (the kiosk may not write into it), so it is renamed where it is.
    note = guest.shell.run("cat /var/lib/gemkiosk/inbox/summer.rejected.txt", check=False)
    if NEW_STONE + ".gemdb" not in note or guest.shell.run(
            "test -e /var/lib/gemkiosk/inbox/summer && echo left || echo moved").strip() != "moved":
        raise CheckFailed("the refused catalogue was not set aside with its reason:\n" + note)
    log("set aside as /var/lib/gemkiosk/inbox/summer.rejected, the reason beside it")
    # The screen keeps the diamond over several frames after the refusal.
    for look in range(3):
        time.sleep(5)
        compare(f"damaged-catalogue-{look + 1}", guest.screenshot("after-damaged"), diamond_start,
                {"the sapphire": sapphire_start}, args.work_dir)

    # Staff copy a catalogue of designs only: the kiosk shows the garnet at once, traced.
    design_start = designs(host, guest, catalogues, figures,
                           {"the diamond": diamond_start, "the sapphire": sapphire_start})
    others = {"the diamond": diamond_start, "the sapphire": sapphire_start}

    # The chain's delivery: a stranger's signature refused, its apt repository's package
    # installed and upgraded. The upgrade's catalogue stays on screen for the steps after.
    chain_start = apt_delivery(host, guest, figures, design_start, others)
    others = {**others, "the garnet": design_start}

    # Frames stop; under KVM the shipped watchdog restarts the kiosk, on the chain's catalogue.
    made = 1 + watchdog(args, guest, choice, figures, chain_start, others)
    # Every restart so far is one the test caused: none from a watchdog on a working kiosk.
    # (StartLimitBurst=5 in 10 minutes: boot, SIGKILL, watchdog and the legacy step make 4.)
    restarts, = guest.unit("NRestarts")
    if int(restarts) != made:
        raise CheckFailed(f"NRestarts={restarts}, the test made {made}:\n" +
                          guest.shell.run("journalctl -u gemkiosk.service -b -o cat --no-pager",
                                          check=False))

    legacy(guest, figures, chain_start, others)


def apt_delivery(host, guest, figures, expected, others):
    """A chain's delivery: a catalogue signed with a key the kiosk does not trust, copied in by
    the clerk, is refused with its line and moved aside; the chain's signed apt repository (a
    file: source, as a mirror would be) installs its catalogue package, which the kiosk shows,
    and then upgrades it. Figures: seconds from `apt-get install` to the kiosk's line and to
    the stone on screen. Returns the host's picture of the upgrade's catalogue."""
    since = guest.shell.run("date +%s").strip()
    guest.shell.run("runuser -u clerk -- cp -r /srv/vm-test/catalogues/stranger "
                    "/var/lib/gemkiosk/inbox/stranger")
    line = guest.wait_for_log("rejected", timeout_s=180, since=since)
    log(f"the kiosk says: {line}")
    if "which is not trusted" not in line or "set aside as" not in line:
        raise CheckFailed(f"the stranger's catalogue was not refused for its key: {line}")
    for look in range(2):
        time.sleep(3)
        compare(f"stranger-refused-{look + 1}", guest.screenshot("stranger"), expected, others,
                guest.work)

    guest.shell.run(
        "install -D -m 0644 /srv/vm-test/repo/chain-archive.gpg /etc/apt/keyrings/chain.gpg && "
        "ln -sfn /srv/vm-test/repo/v1 /srv/chain-repo && "
        "echo 'deb [signed-by=/etc/apt/keyrings/chain.gpg] file:/srv/chain-repo bookworm main' "
        "> /etc/apt/sources.list.d/chain.list")
    # Only the chain's source: the guest has no network to reach Debian's mirror.
    update = ("apt-get update -q -o Dir::Etc::SourceList=/etc/apt/sources.list.d/chain.list "
              "-o Dir::Etc::SourceParts=- -o APT::Get::List-Cleanup=0")
    shown = expected
    for version, (name, stone, _) in CHAIN_VERSIONS.items():
        guest.shell.run(f"ln -sfn /srv/vm-test/repo/v{version} /srv/chain-repo && {update}",
                        timeout_s=300)
        since = guest.shell.run("date +%s").strip()
        started = float(guest.shell.run("cat /proc/uptime").split()[0])
        out = guest.shell.run(f"DEBIAN_FRONTEND=noninteractive apt-get install -y -q "
                              f"{CHAIN_PACKAGE} 2>&1", timeout_s=300)
        log(f"apt-get install {CHAIN_PACKAGE} (version {version}): " +
            " | ".join(l for l in out.splitlines() if l.startswith(("Unpacking", "Setting up"))))
        line = guest.wait_for_log(f"showing catalogue '{name}'", timeout_s=180, since=since)
        logged = float(guest.shell.run("cat /proc/uptime").split()[0]) - started
        log(f"the kiosk says: {line}")
        if "signed by key" not in line:
            raise CheckFailed(f"the kiosk does not say the package's catalogue was signed: {line}")
        picture = host.picture(f"chain-{version}", host.chain_catalogue(version))
        guest.wait_for_picture(f"apt-version-{version}", picture, {**others, "before": shown},
                               timeout_s=300)
        on_screen = float(guest.shell.run("cat /proc/uptime").split()[0]) - started
        figures[f"apt_v{version}_to_log_s"] = logged
        figures[f"apt_v{version}_on_screen_s"] = on_screen
        log(f"{stone} on screen {on_screen:.1f} s after apt-get install began (the kiosk's "
            f"line within {logged:.1f} s)")
        no_warnings(guest, since, f"installing version {version} of the catalogue package")
        shown = picture
    return shown


def designs(host, guest, catalogues, figures, others):
    """A catalogue of designs only (a stone description, no .gemdb) copied in by staff: the
    kiosk validates it, says so and shows the stone drawn by the exact method, as the host's
    kiosk draws the same catalogue. Figures: seconds from the copy to the kiosk's line and to
    the stone on screen. Returns the host's picture of it, for the steps after."""
    since = guest.shell.run("date +%s").strip()
    copied_at = float(guest.shell.run(
        f"runuser -u clerk -- cp -r /srv/vm-test/catalogues/{DESIGN_CATALOGUE} "
        "/var/lib/gemkiosk/inbox/autumn && cat /proc/uptime").split()[0])
    line = guest.wait_for_log(f"showing catalogue '{DESIGN_CATALOGUE}'", timeout_s=180,
                              since=since)
    figures["design_to_log_s"] = float(guest.shell.run("cat /proc/uptime").split()[0]) - copied_at
    log(f"the kiosk says: {line}")
    expected = host.picture("design-start", os.path.join(catalogues, DESIGN_CATALOGUE))
    guest.wait_for_picture("design", expected, others, timeout_s=300)
    figures["design_on_screen_s"] = (float(guest.shell.run("cat /proc/uptime").split()[0]) -
                                     copied_at)
    log(f"the garnet's design on screen {figures['design_on_screen_s']:.1f} s after the copy "
        f"(the kiosk's line after {figures['design_to_log_s']:.1f} s)")
    no_warnings(guest, since, "a catalogue of designs")
    return expected


def stop_and_measure(guest, figures, key):
    """A clean stop (SIGTERM from systemd) and the kiosk's own frame summary, its frame rate
    recorded as figures[key]."""
    since = guest.shell.run("date +%s").strip()
    guest.shell.run("systemctl stop gemkiosk.service", timeout_s=60)
    state, result = guest.unit("ActiveState", "Result")
    if result != "success":
        raise CheckFailed(f"gemkiosk.service stopped with result {result}:\n" + guest.journal())
    summary = guest.wait_for_log(r"frames: \d+ frames in", timeout_s=30, since=since)
    log(f"kiosk in the guest: {summary}")
    figures[key] = frame_rate(summary)
    status = [line for line in guest.journal(400).splitlines() if line.startswith("status:")]
    for line in status:
        log(f"kiosk in the guest: {line}")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--build-dir", required=True)
    parser.add_argument("--source-dir", required=True)
    parser.add_argument("--work-dir", required=True)
    parser.add_argument("--gemkiosk", required=True, help="the host's gemkiosk program")
    parser.add_argument("--gemtables", required=True, help="the host's gemtables program")
    parser.add_argument("--short", action="store_true",
                        help="boot, first frame and a drag only")
    parser.add_argument("--cpus", type=int, default=2)
    parser.add_argument("--accel", choices=("auto", "kvm", "tcg"), default="auto",
                        help="auto: the first of KVM's CPU models that QEMU runs here, else "
                        "plain emulation (TCG); kvm or tcg: that one or fail")
    args = parser.parse_args()
    args.work_dir = os.path.abspath(args.work_dir)
    os.makedirs(args.work_dir, exist_ok=True)

    began = time.monotonic()
    try:
        log(qemu_version())
    except QemuMissing as missing:
        log(f"skipped: {missing} (scripts/install-deps.sh installs QEMU)")
        return SKIP

    host = Host(args)
    log("building the package and the catalogues")
    deb = host.package()
    keys = host.keys()
    catalogues = host.catalogues(keys)
    repository = host.repository(keys)
    image = os.path.join(args.work_dir, "image")
    made = subprocess.run([os.path.join(HERE, "image.sh"), "--deb", deb, "--catalogues",
                           catalogues, "--repo", repository, "--out", image])
    if made.returncode == SKIP:
        return SKIP
    if made.returncode != 0:
        log("image.sh failed")
        return 1
    log(f"image ready after {time.monotonic() - began:.0f} s")

    # With the guest's own kernel: a KVM may start QEMU and still not run it.
    try:
        choice = choose_accelerator(accelerator=args.accel, cpus=args.cpus,
                                    kernel=os.path.join(image, "vmlinuz"))
    except VmError as failure:
        log(f"FAILED: {failure}")
        return 1
    for line in choice.report():
        log(line)

    figures = {"accelerator": choice.accelerator, "cpu": choice.cpu}
    try:
        machine = Machine(image, args.work_dir, choice, cpus=args.cpus)
    except VmError as failure:
        log(f"FAILED: {failure}")
        return 1
    log(f"booting under QEMU ({choice.describe()}, {args.cpus} CPUs)")
    try:
        shell = machine.connect_shell(timeout_s=600)
        log(f"the guest's shell answered after {time.monotonic() - machine.started:.0f} s")
        guest = Guest(machine, shell, args.work_dir)
        scenario(args, host, guest, catalogues, figures, choice)
        stop_and_measure(guest, figures,
                         "frames_per_s" if args.short else "legacy_frames_per_s")
        figures["scenario_s"] = time.monotonic() - machine.started
        figures["with_image_s"] = time.monotonic() - began
        # Frame rates under emulation are tenths of a frame per second: two decimals.
        log("figures: " + ", ".join(
            f"{k} {v:.2f}" if k.endswith("frames_per_s") else
            f"{k} {v:.1f}" if isinstance(v, float) else f"{k} {v}" for k, v in figures.items()))
    except (CheckFailed, VmError) as failure:
        log(f"FAILED: {failure}")
        log("the guest's serial console, last lines:\n" + machine.serial_tail())
        return 1
    finally:
        machine.stop()
    # The guest's disk (over a gigabyte) goes; the screenshots and logs stay.
    os.remove(os.path.join(image, "root.img"))
    log(f"passed in {time.monotonic() - began:.0f} s; pictures in {args.work_dir}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
