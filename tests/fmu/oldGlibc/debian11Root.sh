#!/bin/bash
# debian11Root.sh <dir>: a minimal Debian 11 (bullseye, glibc 2.31) root in
# <dir> with its python3, made with debootstrap --variant=minbase from the
# Debian archive this machine's apt uses (the entry of its own release,
# read with apt-get indextargets; DEBIAN11_MIRROR=<url> overrides it).
#
# Idempotent: <dir>/.debian11Root holds the settings and is written only
# after debootstrap succeeded; a root without it (a run killed halfway) or
# with other settings is removed and made again, else it is reused. Needs
# root (debootstrap) and about 250 MB; takes a minute or two.
set -eu -o pipefail
export PATH=/usr/sbin:/sbin:/usr/bin:/bin

fail()
{
    echo "debian11Root.sh: error: $*" >&2
    exit 1
}

[ $# -eq 1 ] || fail "usage: debian11Root.sh <dir>"
[ "$(id -u)" = 0 ] || fail "debootstrap needs root (run the test as root)"
command -v debootstrap >/dev/null \
    || fail "debootstrap is not installed: run bin/setup -tests (etc/debian-packages-tests)"
mkdir -p "$(dirname "$1")"
root=$(realpath -m "$1")

mirror=${DEBIAN11_MIRROR:-}
if [ -z "$mirror" ]; then
    codename=$(. /etc/os-release && echo "${VERSION_CODENAME:-}")
    mirror=$(apt-get indextargets --no-release-info --format '$(REPO_URI)' \
        "Release: $codename" 'Identifier: Packages' 2>/dev/null | head -n 1)
    [ -n "$mirror" ] \
        || fail "no apt source for $codename in /etc/apt/sources.list{,.d}: set DEBIAN11_MIRROR"
fi
settings="bullseye minbase python3 $mirror"

# One maker at a time; the lock file sits beside the root
exec 9>"$root.lock"
flock 9

stamp=$root/.debian11Root
if [ -f "$stamp" ] && [ "$(cat "$stamp")" = "$settings" ]; then
    echo "debian11Root.sh: reusing $root ($settings)"
    exit 0
fi

# Only what this script makes is removed: a root, or debootstrap's leftovers
if [ "$root" = / ] || { [ -n "$(ls -A "$root" 2>/dev/null)" ] && [ ! -e "$stamp" ] \
        && [ ! -d "$root/debootstrap" ] && [ ! -f "$root/etc/debian_version" ]; }; then
    fail "$root is neither empty nor a Debian root: remove it or choose another folder"
fi
# A previous debootstrap killed halfway may have left /proc or /sys mounted
awk -v prefix="$root/" 'index($2, prefix) == 1 { print $2 }' /proc/self/mounts \
    | sort -r | while read -r mount; do umount -l "$mount"; done
rm -rf --one-file-system "$root"

echo "debian11Root.sh: debootstrap $settings into $root"
start=$SECONDS
log=$root.log
if ! debootstrap --variant=minbase --include=python3 bullseye "$root" "$mirror" \
    >"$log" 2>&1; then
    tail -n 15 "$log" >&2
    fail "debootstrap of Debian 11 from $mirror failed (log: $log): is the" \
         "archive reachable, and does it still carry bullseye (else set" \
         "DEBIAN11_MIRROR, e.g. to http://archive.debian.org/debian)?"
fi
rm -f "$root"/var/cache/apt/archives/*.deb
echo "$settings" >"$stamp"
echo "debian11Root.sh: made in $((SECONDS - start)) s"
