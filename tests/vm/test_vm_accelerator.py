#!/usr/bin/env python3
"""The VM test's choice of accelerator (vm_machine.choose_accelerator), against a stand-in
for qemu-system-x86_64: a small Python program that fails the way a real QEMU does on a given
host, or serves just enough QMP (greeting, qmp_capabilities, query-status, quit) to pass.
Needs neither QEMU nor root nor /dev/kvm."""

import json
import os
import shutil
import sys
import tempfile
import time
import unittest

sys.dont_write_bytecode = True
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import vm_machine  # noqa: E402
from vm_machine import Candidate, VmError  # noqa: E402

# The stand-in. MODE says how it treats KVM; everything else (TCG, and the KVM CPUs a mode does
# not name) starts and answers QMP. Each start appends its command line to CALLS.
STAND_IN = r'''#!PYTHON
import json, os, socket, sys, time
MODE = "@MODE@"
CALLS = "@CALLS@"
args = sys.argv[1:]
with open(CALLS, "a") as f:
    f.write(json.dumps(args) + "\n")
value = lambda flag: args[args.index(flag) + 1]
accel = value("-machine").split("accel=")[1].split(",")[0]
cpu = value("-cpu")
path = value("-qmp").split("unix:")[1].split(",")[0]
name = "qemu-system-x86_64"

if accel == "kvm" and MODE == "msr-refused" and cpu.split(",")[0] in ("host", "max") \
        and "-arch-capabilities" not in cpu:
    print(f"{name}: error: failed to set MSR 0x10a to 0x69", flush=True)
    print(f"{name}: ../../target/i386/kvm/kvm.c:3183: kvm_buf_set_msrs: Assertion "
          "`ret == cpu->kvm_msr_buf->nmsrs' failed.", flush=True)
    os.abort()
if accel == "kvm" and MODE == "no-kvm":
    print("Could not access KVM kernel module: No such file or directory", flush=True)
    print(f"{name}: -machine q35,accel=kvm: failed to initialize kvm: No such file or directory",
          flush=True)
    sys.exit(1)

server = socket.socket(socket.AF_UNIX, socket.SOCK_STREAM)
server.bind(path)
server.listen(1)
if accel == "kvm" and MODE == "silent-kvm":
    # Takes the connection and never says a word.
    connection, _ = server.accept()
    time.sleep(3600)
dies_late = accel == "kvm" and MODE == "kvm-dies-late" and cpu == "host"
# A kernel to boot: its first line on the serial port, unless this KVM cannot run it.
if "-kernel" in args and not (accel == "kvm" and MODE == "kvm-kernel-hangs"):
    with open(value("-serial").split("file:")[1], "w") as f:
        f.write("[    0.000000] Linux version 6.1.0-50-amd64 (debian-kernel@lists.debian.org)\n")

connection, _ = server.accept()
stream = connection.makefile("rw")
def send(message):
    stream.write(json.dumps(message) + "\n")
    stream.flush()
send({"QMP": {"version": {"qemu": {"major": 7, "minor": 2, "micro": 0}}, "capabilities": []}})
for line in stream:
    command = json.loads(line)["execute"]
    if command == "qmp_capabilities":
        send({"return": {}})
    elif command == "query-status":
        # An event first: the client must skip it.
        send({"event": "RESUME", "timestamp": {"seconds": 0, "microseconds": 0}})
        send({"return": {"status": "running", "singlestep": False, "running": True}})
        if dies_late:
            print(f"{name}: error: failed to set MSR 0x10a to 0x69", flush=True)
            time.sleep(0.1)
            os.abort()
    elif command == "quit":
        send({"return": {}})
        sys.exit(0)
    else:
        send({"error": {"class": "CommandNotFound", "desc": command}})
'''


class ChooseAccelerator(unittest.TestCase):
    def setUp(self):
        self.folder = tempfile.mkdtemp(prefix="gem-vm-accel-test-")
        self.calls = os.path.join(self.folder, "calls")

    def tearDown(self):
        shutil.rmtree(self.folder, ignore_errors=True)

    def stand_in(self, mode):
        path = os.path.join(self.folder, "qemu-" + mode)
        with open(path, "w") as f:
            f.write(STAND_IN.replace("PYTHON", sys.executable).replace("@MODE@", mode)
                    .replace("@CALLS@", self.calls))
        os.chmod(path, 0o755)
        return path

    def tried(self):
        with open(self.calls) as f:
            calls = [json.loads(line) for line in f]
        return [(c[c.index("-machine") + 1], c[c.index("-cpu") + 1]) for c in calls], calls

    def choose(self, mode, **kwargs):
        kwargs.setdefault("timeout_s", 2.0)
        kwargs.setdefault("settle_s", 0.3)
        return vm_machine.choose_accelerator(qemu=self.stand_in(mode), **kwargs)

    def test_host_refusing_arch_capabilities_gets_host_cpu_without_it(self):
        choice = self.choose("msr-refused", cpus=2, memory_mb=1536)
        self.assertEqual(choice.candidate, Candidate("kvm", "host,-arch-capabilities"))
        self.assertEqual([c for c, _ in choice.passed_over], [Candidate("kvm", "host")])
        reason = choice.passed_over[0][1]
        self.assertIn("killed by SIGABRT", reason)
        self.assertIn("failed to set MSR 0x10a", reason)
        tried, calls = self.tried()
        self.assertEqual(tried, [("q35,accel=kvm", "host"),
                                 ("q35,accel=kvm", "host,-arch-capabilities")])
        # A probe is the real machine without its guest: same CPUs and memory, no kernel.
        for call in calls:
            self.assertEqual(call[call.index("-smp") + 1], "2")
            self.assertEqual(call[call.index("-m") + 1], "1536")
            self.assertNotIn("-kernel", call)
        self.assertEqual(choice.report()[0],
                         "QEMU runs under kvm with -cpu host,-arch-capabilities")
        self.assertTrue(choice.report()[1].startswith("passed over kvm with -cpu host: QEMU "
                                                      "killed by SIGABRT"))

    def test_with_a_kernel_the_choice_is_the_same_where_it_boots(self):
        kernel = os.path.join(self.folder, "vmlinuz")
        open(kernel, "w").close()
        choice = self.choose("msr-refused", kernel=kernel, kernel_timeout_s=2.0)
        self.assertEqual(choice.candidate, Candidate("kvm", "host,-arch-capabilities"))
        _, calls = self.tried()
        self.assertEqual(calls[-1][calls[-1].index("-kernel") + 1], kernel)

    def test_kvm_that_starts_but_cannot_run_the_kernel_is_passed_over(self):
        kernel = os.path.join(self.folder, "vmlinuz")
        open(kernel, "w").close()
        began = time.monotonic()
        choice = self.choose("kvm-kernel-hangs", kernel=kernel, kernel_timeout_s=1.0)
        self.assertEqual(choice.candidate, Candidate("tcg", "max"))
        self.assertEqual(len(choice.passed_over), 3)
        for _, reason in choice.passed_over:
            self.assertEqual(reason, "QEMU runs, but the guest's kernel printed nothing in 1 s")
        self.assertLess(time.monotonic() - began, 15.0)

    def test_without_a_kernel_such_a_kvm_looks_usable(self):
        # What the firmware-only probe can see: the reason to give it the guest's kernel.
        choice = self.choose("kvm-kernel-hangs")
        self.assertEqual(choice.candidate, Candidate("kvm", "host"))

    def test_no_kvm_at_all_falls_back_to_tcg(self):
        choice = self.choose("no-kvm")
        self.assertEqual(choice.candidate, Candidate("tcg", "max"))
        self.assertEqual([c for c, _ in choice.passed_over],
                         [c for c in vm_machine.CANDIDATES if c.accelerator == "kvm"])
        for _, reason in choice.passed_over:
            self.assertIn("exited with status 1", reason)
            self.assertIn("failed to initialize kvm", reason)

    def test_kvm_whose_qmp_never_answers_is_passed_over_after_the_timeout(self):
        began = time.monotonic()
        choice = self.choose("silent-kvm", timeout_s=1.0)
        elapsed = time.monotonic() - began
        self.assertEqual(choice.candidate, Candidate("tcg", "max"))
        self.assertEqual(len(choice.passed_over), 3)
        for _, reason in choice.passed_over:
            self.assertIn("QMP did not answer in 1 s", reason)
        # Three silent candidates of about 1 s each, then TCG: not the real machine's minutes.
        self.assertLess(elapsed, 10.0)

    def test_kvm_that_dies_once_its_cpus_run_is_passed_over(self):
        choice = self.choose("kvm-dies-late")
        self.assertEqual(choice.candidate, Candidate("kvm", "host,-arch-capabilities"))
        reason = choice.passed_over[0][1]
        self.assertIn("after starting", reason)
        self.assertIn("SIGABRT", reason)

    def test_forced_tcg_tries_nothing_else(self):
        choice = self.choose("msr-refused", accelerator="tcg")
        self.assertEqual(choice.candidate, Candidate("tcg", "max"))
        self.assertEqual(choice.passed_over, [])
        self.assertEqual(self.tried()[0], [("q35,accel=tcg", "max")])

    def test_forced_kvm_where_kvm_cannot_run_names_every_candidate(self):
        with self.assertRaises(VmError) as raised:
            self.choose("no-kvm", accelerator="kvm")
        message = str(raised.exception)
        for cpu in ("host", "host,-arch-capabilities", "qemu64"):
            self.assertIn(f"kvm -cpu {cpu}: QEMU exited with status 1", message)
        self.assertNotIn("tcg", message)

    def test_a_missing_qemu_says_so_apart_from_a_failing_one(self):
        with self.assertRaises(vm_machine.QemuMissing) as raised:
            vm_machine.choose_accelerator(qemu=os.path.join(self.folder, "no-such-qemu"),
                                          timeout_s=1.0, settle_s=0.1)
        self.assertIn("cannot run", str(raised.exception))
        with self.assertRaises(vm_machine.QemuMissing):
            vm_machine.qemu_version(os.path.join(self.folder, "no-such-qemu"))


if __name__ == "__main__":
    unittest.main()
