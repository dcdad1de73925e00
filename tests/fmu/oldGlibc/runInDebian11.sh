#!/bin/bash
# runInDebian11.sh <work dir> <root dir> <FMI headers> <example dir> <fmu>...
#
# The test fmu.oldGlibc: the connector FMUs <fmu>... and the example
# <example dir> (examples/customConnector, built here with its own Makefile
# against <FMI headers>) are stepped by stepFmus.py on this machine, then
# in the Debian 11 root <root dir> (debian11Root.sh: glibc 2.31, made once)
# with that root's python3 and glibc: no library of this machine can be
# mapped there. Each FMU must load, instantiate, initialize, step and free
# with fmi2OK, and its outputs must agree with this machine's. Needs root
# (debootstrap, chroot); work files in <work dir>.
set -eu -o pipefail
export PATH=$PATH:/usr/sbin:/sbin
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
start=$SECONDS

fail()
{
    echo "runInDebian11.sh: error: $*" >&2
    exit 1
}

[ $# -ge 5 ] || fail "usage: runInDebian11.sh <work dir> <root dir> <FMI headers> <example dir> <fmu>..."
work=$1 root=$2 fmiInclude=$3 example=$4
shift 4
[ "$(id -u)" = 0 ] || fail "the Debian 11 root needs root (debootstrap, chroot)"

rm -rf "$work"
mkdir -p "$work/customConnector"
cp "$example"/bungee.c "$example"/modelDescription.xml "$example"/Makefile "$work/customConnector/"
make -s -C "$work/customConnector" FMI_INCLUDE="$fmiInclude" bungee.fmu >"$work/make.log" 2>&1 \
    || { cat "$work/make.log" >&2; fail "the example $example does not build"; }
fmus=("$@" "$work/customConnector/bungee.fmu")
# The bungee pulls only when longer than its rest length, 1 m
starts=(--set 'bungee:B.r[1]=1.2')

echo "== On this machine"
python3 "$here/stepFmus.py" --output "$work/host.json" "${starts[@]}" "${fmus[@]}"

"$here/debian11Root.sh" "$root"
inside=/srv/fmuOldGlibc
rm -rf "$root$inside"
mkdir -p "$root$inside"
cp "$here/stepFmus.py" "$work/host.json" "${fmus[@]}" "$root$inside/"
paths=()
for fmu in "${fmus[@]}"; do
    paths+=("$inside/$(basename "$fmu")")
done

echo "== In Debian 11 ($root)"
chroot "$root" /usr/bin/env -i PATH=/usr/bin:/bin HOME=/root \
    python3 "$inside/stepFmus.py" --expect-glibc 2.31 --reference "$inside/host.json" \
    "${starts[@]}" "${paths[@]}"
echo "runInDebian11.sh: passed in $((SECONDS - start)) s"
