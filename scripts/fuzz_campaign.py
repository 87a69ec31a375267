#!/usr/bin/env python3
"""A long fuzzing campaign: every libFuzzer target of the suite (CTest label "fuzz") run for
SECONDS each, one after the other, with the very command, seeds and corpus CTest gives it
(only -max_total_time changes). Prints one Markdown row a target: seconds, inputs run, the
edges covered (libFuzzer's "cov") and features ("ft") at the end, and the crashes, timeouts and
out-of-memory inputs it wrote. Run from the repository root after building build/test and
running the fuzz tests once (they build the targets and write the seeds):

    python3 scripts/fuzz_campaign.py 600 [TARGET ...]      (default: every target)
"""
import json
import os
import re
import subprocess
import sys
import time

BUILD = "build/test"


def fuzz_commands():
    listing = subprocess.run(["ctest", "--test-dir", BUILD, "-L", "fuzz", "--show-only=json-v1"],
                             check=True, capture_output=True, text=True).stdout
    commands = {}
    for test in json.loads(listing)["tests"]:
        command = test.get("command") or []
        if any(arg.startswith("-max_total_time=") for arg in command):
            commands[test["name"]] = command
    return commands


def artifacts(prefix):
    folder, stem = os.path.split(prefix)
    return {name for name in os.listdir(folder)
            if name.startswith(stem) and re.match(r"(crash|timeout|oom|leak)-", name[len(stem):])}


def run(name, command, seconds):
    command = [f"-max_total_time={seconds}" if arg.startswith("-max_total_time=") else arg
               for arg in command]
    prefix = next(arg.split("=", 1)[1] for arg in command if arg.startswith("-artifact_prefix="))
    before = artifacts(prefix)
    started = time.monotonic()
    # -print_final_stats=1: libFuzzer's own count of the inputs it ran.
    # errors="replace": a reader may echo the fuzzer's bytes to stderr (libevemu does).
    done = subprocess.run(command + ["-print_final_stats=1"], capture_output=True, text=True,
                          errors="replace")
    took = time.monotonic() - started
    log = done.stderr
    runs = re.findall(r"stat::number_of_executed_units:\s*(\d+)", log)
    cov = re.findall(r"\bcov: (\d+) ft: (\d+)", log)
    found = sorted(artifacts(prefix) - before)
    with open(os.path.join(os.path.dirname(prefix), f"{name}-campaign.log"), "w") as out:
        out.write(log)
    edges, features = cov[-1] if cov else ("?", "?")
    status = "none" if done.returncode == 0 and not found else \
        f"exit {done.returncode}: " + ", ".join(found)
    return f"| {name} | {took:.0f} | {runs[-1] if runs else '?'} | {edges} | {features} | {status} |"


def main():
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    seconds = int(sys.argv[1])
    commands = fuzz_commands()
    names = sys.argv[2:] or sorted(commands)
    print("| target | seconds | inputs run | edges (cov) | features (ft) | crashes |")
    print("|---|---|---|---|---|---|")
    for name in names:
        if name not in commands:
            sys.exit(f"no fuzz target {name} (targets: {', '.join(sorted(commands))})")
        print(run(name, commands[name], seconds), flush=True)


if __name__ == "__main__":
    main()
