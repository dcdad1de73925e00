#!/bin/bash
# runInDebian11.sh <work dir> <root dir> <FMI headers> <FMI 3.0 headers> <example dir> <fmu>...
#
# The test fmu.oldGlibc: the connector FMUs <fmu>... (FMI 2.0 and 3.0) and
# the example <example dir> (examples/customConnector: bungee.fmu and
# bungee3.fmu, built here with its own Makefile against <FMI headers> and
# <FMI 3.0 headers>) are stepped by stepFmus.py on this machine, where the
# 3.0 FMU of each connector must give the 2.0 FMU's outputs bitwise, then
# in the Debian 11 root <root dir> (debian11Root.sh: glibc 2.31, made once)
# with that root's python3 and glibc: no library of this machine can be
# mapped there. Each FMU must load, instantiate, initialize, step and free
# with fmi2OK (fmi3OK), and its outputs must agree with this machine's.
# Needs root (debootstrap, chroot); work files in <work dir>.
set -eu -o pipefail
export PATH=$PATH:/usr/sbin:/sbin
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
start=$SECONDS

fail()
{
    echo "runInDebian11.sh: error: $*" >&2
    exit 1
}

[ $# -ge 6 ] || fail "usage: runInDebian11.sh <work dir> <root dir> <FMI headers> <FMI 3.0 headers> <example dir> <fmu>..."
work=$1 root=$2 fmiInclude=$3 fmi3Include=$4 example=$5
shift 5
[ "$(id -u)" = 0 ] || fail "the Debian 11 root needs root (debootstrap, chroot)"

rm -rf "$work"
mkdir -p "$work/customConnector"
cp -r "$example"/bungee.c "$example"/bungee3.c "$example"/modelDescription.xml "$example"/fmi3 \
    "$example"/Makefile "$work/customConnector/"
make -s -C "$work/customConnector" FMI_INCLUDE="$fmiInclude" FMI3_INCLUDE="$fmi3Include" \
    bungee.fmu bungee3.fmu >"$work/make.log" 2>&1 \
    || { cat "$work/make.log" >&2; fail "the example $example does not build"; }
fmus=("$@" "$work/customConnector/bungee.fmu" "$work/customConnector/bungee3.fmu")
# The bungee pulls only when longer than its rest length, 1 m
starts=(--set 'bungee:B.r[1]=1.2' --set 'bungee3:B.r[1]=1.2')

echo "== On this machine"
python3 "$here/stepFmus.py" --output "$work/host.json" --same-versions "${starts[@]}" "${fmus[@]}"

"$here/debian11Root.sh" "$root"
inside=/srv/fmuOldGlibc
rm -rf "$root$inside"
mkdir -p "$root$inside"
cp "$here"/stepFmus.py "$here"/fmucalls.py "$here"/fmudescription.py "$here"/fmucompare.py \
    "$work/host.json" "$root$inside/"
# A folder per FMU: a connector's 2.0 and 3.0 FMUs have the same file name
paths=()
for fmu in "${fmus[@]}"; do
    folder=$inside/${#paths[@]}
    mkdir "$root$folder"
    cp "$fmu" "$root$folder/"
    paths+=("$folder/$(basename "$fmu")")
done

echo "== In Debian 11 ($root)"
chroot "$root" /usr/bin/env -i PATH=/usr/bin:/bin HOME=/root \
    python3 "$inside/stepFmus.py" --expect-glibc 2.31 --reference "$inside/host.json" \
    "${starts[@]}" "${paths[@]}"
echo "runInDebian11.sh: passed in $((SECONDS - start)) s"
