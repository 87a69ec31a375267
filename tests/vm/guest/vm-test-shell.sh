#!/bin/sh
# The VM test's way into the guest: reads one shell command per line from the second serial
# port, runs it as root and answers with its output and a line "VM-TEST-DONE <status>". Raw
# mode and no echo, so what comes back is the command's output alone.
stty -F /dev/ttyS1 raw -echo 115200
exec </dev/ttyS1 >/dev/ttyS1 2>&1
echo "VM-TEST-SHELL-READY"
while IFS= read -r line; do
  sh -c "$line"
  echo "VM-TEST-DONE $?"
done
