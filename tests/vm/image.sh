#!/usr/bin/env bash
# Builds the disk of the virtual shop machine the VM test boots: Debian 12 with a kernel,
# systemd, Mesa and gemkiosk's Debian package installed as a shop would install it, plus the
# test's own pieces (tests/vm/guest/: the kiosk's config, a root shell on the second serial
# port for the test to drive the guest through, and the catalogues the test shows).
#
#   image.sh --deb gemkiosk_*.deb --catalogues DIR --repo DIR --out DIR
#
# DIR (catalogues) holds folders: `first` becomes the default catalogue, the others are staged
# in /srv/vm-test/catalogues for the test to copy into the inbox. DIR (repo) is the chain's apt
# repository, staged in /srv/vm-test/repo; its chain.pub becomes the key the kiosk trusts
# (/etc/gemkiosk/keys/chain.pub, named by guest/gemkiosk.toml). Writes OUT/root.img (ext4),
# OUT/vmlinuz and OUT/initrd.img.
#
# The Debian part (mmdebstrap, 4 to 6 minutes and about 300 MB of downloads the first time) is
# cached as a tarball under $GEM_VM_CACHE (default ~/.cache/gemkiosk-vm), keyed by its package
# list; the package's layer is added to a fresh copy every time (about 30 s).
#
# Exits 77 (CTest: skipped) when this machine cannot build the image at all: not root (the
# image's files belong to its own users, and the package installs in a chroot), no mmdebstrap
# or mke2fs, or no Debian mirror reachable.
set -euo pipefail

here=$(cd "$(dirname "$0")" && pwd)
deb= catalogues= repo= out=
while [ $# -gt 0 ]; do
  case $1 in
    --deb) deb=$(realpath "$2"); shift 2 ;;
    --catalogues) catalogues=$(realpath "$2"); shift 2 ;;
    --repo) repo=$(realpath "$2"); shift 2 ;;
    --out) out=$2; shift 2 ;;
    *) echo "image.sh: unknown argument $1" >&2; exit 2 ;;
  esac
done
[ -f "$deb" ] && [ -d "$catalogues/first" ] && [ -f "$repo/chain.pub" ] && [ -n "$out" ] ||
  { echo "usage: image.sh --deb FILE.deb --catalogues DIR --repo DIR --out DIR" >&2; exit 2; }

skip() { echo "image.sh: skipped: $*" >&2; exit 77; }
[ "$(id -u)" -eq 0 ] || skip "building the guest's disk needs root (chroot, file owners)"
for tool in mmdebstrap mke2fs; do
  command -v $tool >/dev/null || skip "$tool is not installed (scripts/install-deps.sh)"
done

mirror=${GEM_VM_MIRROR:-http://deb.debian.org/debian}
cache=${GEM_VM_CACHE:-${XDG_CACHE_HOME:-$HOME/.cache}/gemkiosk-vm}
mkdir -p "$cache" "$out"

# The guest's Debian packages: a kernel and an init, logind (libpam-systemd: the kiosk's
# PAM session) and the system bus it answers on, evemu-record (the test records what the
# guest's kernel delivers), and whatever the kiosk's package depends on. Versions and
# alternatives are dropped: the mirror's bookworm has what the package was built against.
packages="linux-image-amd64 systemd systemd-sysv udev dbus libpam-systemd kmod evemu-tools"
depends=$(dpkg-deb -f "$deb" Depends | tr ',' '\n' | sed -e 's/|.*//' -e 's/(.*)//' -e 's/:any//' -e 's/[[:space:]]//g')
packages=$(printf '%s\n' $packages $depends | sort -u | tr '\n' ' ')
# Raise recipe when the mmdebstrap command below changes: the cached tarball is then rebuilt.
recipe=1
key=$(printf '%s\n%s\n%s\n' "$mirror" "$packages" "$recipe" | sha256sum | cut -c1-16)
base=$cache/bookworm-$key.tar

if [ ! -f "$base" ]; then
  address=$(echo "$mirror" | sed -E 's#^[a-z]+://([^/]+).*#\1#')
  host=${address%%:*}
  port=80
  case $mirror in https:*) port=443 ;; esac
  case $address in *:*) port=${address##*:} ;; esac
  timeout 15 bash -c "exec 3<>/dev/tcp/$host/$port" 2>/dev/null ||
    skip "the Debian mirror $address cannot be reached, and no guest image is cached in $cache"
  echo "image.sh: building the Debian 12 guest in $base (once; about 5 minutes)" >&2
  # Documentation, manual pages and translations are left out: the guest never reads them.
  mmdebstrap --variant=apt --mode=root --include="$(echo $packages | tr ' ' ',')" \
    --dpkgopt='path-exclude=/usr/share/man/*' --dpkgopt='path-exclude=/usr/share/doc/*' \
    --dpkgopt='path-include=/usr/share/doc/*/copyright' \
    --dpkgopt='path-exclude=/usr/share/locale/*' \
    --customize-hook='echo "/dev/vda / ext4 rw,relatime 0 1" > "$1/etc/fstab"' \
    --customize-hook='echo gemkiosk-vm > "$1/etc/hostname"' \
    bookworm "$base.part.tar" "$mirror" >"$cache/mmdebstrap-$key.log" 2>&1 || {
    tail -20 "$cache/mmdebstrap-$key.log" >&2
    # A mirror that fails mid-way is this machine's network, not the project: skipped. Any
    # other failure (a package that does not exist, a hook that fails) is the test's.
    if grep -qE "Could not connect|Temporary failure resolving|Failed to fetch|Connection (timed out|refused)" \
        "$cache/mmdebstrap-$key.log"; then
      skip "mmdebstrap could not download from $mirror (network)"
    fi
    echo "image.sh: mmdebstrap failed" >&2
    exit 1
  }
  mv "$base.part.tar" "$base"
fi

root=$out/rootfs
rm -rf "$root" && mkdir -p "$root"
tar -C "$root" -xpf "$base"
cp "$root"/boot/vmlinuz-* "$out/vmlinuz"
cp "$root"/boot/initrd.img-* "$out/initrd.img"

# The kiosk's package, installed with dpkg as on a shop's machine: its maintainer scripts make
# the gemkiosk user, its state folders and enable the units.
cp "$deb" "$root/tmp/gemkiosk.deb"
chroot "$root" dpkg -i /tmp/gemkiosk.deb >"$out/dpkg.log" 2>&1 ||
  { cat "$out/dpkg.log" >&2; echo "image.sh: dpkg -i failed in the guest" >&2; exit 1; }
rm "$root/tmp/gemkiosk.deb"

# A member of staff, allowed to drop catalogues into the kiosk's inbox.
chroot "$root" useradd --create-home --no-user-group --gid users --groups gemkiosk-staff clerk

# The test's config (a modest mode on the virtual display) and catalogues.
install -m 0644 "$here/guest/gemkiosk.toml" "$root/etc/gemkiosk/gemkiosk.toml"
# (A package built without the default catalogue has no /usr/share/gemkiosk.)
rm -rf "$root/usr/share/gemkiosk/catalogue"
mkdir -p "$root/usr/share/gemkiosk"
cp -r "$catalogues/first" "$root/usr/share/gemkiosk/catalogue"
mkdir -p "$root/srv/vm-test/catalogues"
for dir in "$catalogues"/*/; do
  name=$(basename "$dir")
  [ "$name" = first ] || cp -r "$dir" "$root/srv/vm-test/catalogues/$name"
done
# The chain's repository (apt reads it as a file: source) and the catalogues' trusted key.
cp -r "$repo" "$root/srv/vm-test/repo"
install -D -m 0644 "$repo/chain.pub" "$root/etc/gemkiosk/keys/chain.pub"
chmod -R a+rX "$root/srv/vm-test" "$root/usr/share/gemkiosk/catalogue"

# The watchdog's limit for a machine that draws a frame every few seconds, added by a generator
# only when the kernel's command line asks (under plain emulation; vm_machine.py).
install -D -m 0644 "$here/guest/gemkiosk-watchdog.conf" \
  "$root/usr/local/share/vm-test/gemkiosk-watchdog.conf"
install -D -m 0755 "$here/guest/vm-test-watchdog-generator" \
  "$root/etc/systemd/system-generators/vm-test-watchdog"

# The test's way into the guest.
install -m 0755 "$here/guest/vm-test-shell.sh" "$root/usr/local/bin/vm-test-shell"
install -m 0644 "$here/guest/vm-test-shell.service" "$root/etc/systemd/system/"
chroot "$root" systemctl enable vm-test-shell.service >/dev/null 2>&1

size_mb=$(( $(du -sm "$root" | cut -f1) * 13 / 10 + 256 ))
rm -f "$out/root.img"
mke2fs -q -t ext4 -d "$root" -L root "$out/root.img" "${size_mb}M"
rm -rf "$root"
echo "image.sh: $out/root.img (${size_mb} MB) with $(basename "$deb")" >&2
