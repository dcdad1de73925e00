#!/bin/bash
#------------------------------------------------------------------------------
# Every OpenFOAM-side source of the project, compiled against a newer OpenFOAM
# (ESI v2312 or v2506) as a user with their own OpenFOAM builds it: that
# version's etc/bashrc sourced, then the project's etc/bashrc (which must keep
# that environment: FOAMFMI_OPENFOAM=own), then foam-fmi-bridge/Allwmake with
# wmake's "objects" target (compile, do not link: the headers, wmake and the
# solver sources are there, no libraries).
#
# Checks:
#  - every source of every Make/files under foam-fmi-bridge/ compiles to an
#    object (so a Make folder left out of foam-fmi-bridge/Allwmake fails);
#  - no warning in the project's own files with -Wsuggest-override: an
#    overriding member without `override` could silently stop overriding
#    when OpenFOAM changes a signature, as writeObject did in v2006;
#  - an OpenFOAM whose FOAM_LIBBIN lacks a library a part links (liboverset.so
#    for the overset solver) stops foam-fmi-bridge/Allwmake at once with a
#    message naming it.
#
# The sources, beside the repository (or in $FOAMFMI_OPENFOAM_TARBALL):
#   v2312  ../shared/openfoam-v2312/openfoam-v2312-src.tar.xz (of2312/: src
#          with most lnInclude folders, the solver sources, wmake; a solver
#          it lacks, interIsoFoam, from OpenFOAM-v2312.tar.xz beside it)
#   v2506  ../shared/openfoam-v2506/OpenFOAM-v2506.tar.xz (OpenFOAM-v2506/:
#          the whole release, no lnInclude folders)
# unpacked into the build folder given as the argument, never into the
# repository. Without it the test is skipped (exit 77) with a message, except
# under CI=true, where that is a failure.
#
# Usage: compileOpenFOAM.sh v2312|v2506 BUILD_DIR   (about 2 minutes on 2 cores)
#------------------------------------------------------------------------------
set -u -o pipefail

top=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd -P)
[ "$#" -eq 2 ] || { echo "Usage: $0 v2312|v2506 BUILD_DIR" 1>&2; exit 2; }
version=$1
api=${version#v}
case "$version" in
    v2312) tarName=openfoam-v2312-src.tar.xz treeName=of2312 ;;
    v2506) tarName=OpenFOAM-v2506.tar.xz treeName=OpenFOAM-v2506 ;;
    *) echo "Usage: $0 v2312|v2506 BUILD_DIR" 1>&2; exit 2 ;;
esac
testName=compile${version^}
work="$(realpath -m "$2")/openfoam-$version"
start=$SECONDS

fail()
{
    echo "FAIL [$testName]: $*" 1>&2
    exit 1
}

pass()
{
    echo "ok   [$testName]: $*"
}

tarball="${FOAMFMI_OPENFOAM_TARBALL:-$top/../shared/openfoam-$version/$tarName}"
if [ ! -f "$tarball" ]
then
    if [ "${CI:-}" = true ]
    then
        fail "$tarball not found: CI must check the build against $version"
    fi
    echo "SKIP [$testName]: $tarball not found (../shared beside the" \
         "repository holds it); the build against $version is not checked"
    exit 77
fi

# --- The sources, wmake's tools, lnInclude folders ---------------------------
mkdir -p "$work" || fail "cannot create $work"
tree="$work/$treeName"
stamp="$tree/.unpacked-$(stat -c '%s-%Y' "$tarball")"
if [ ! -f "$stamp" ]
then
    rm -rf "$tree"
    tar -xJf "$tarball" -C "$work" || fail "cannot unpack $tarball into $work"
    [ -f "$tree/etc/bashrc" ] || fail "$tarball has no $treeName/etc/bashrc"
    touch "$stamp"
fi

# The project's Make/options, which name the OpenFOAM folders it needs
makeOptions=$(find "$top/foam-fmi-bridge" -path '*/Make/options')

# The solver sources the project rebuilds that the tree lacks (v2312's
# compile-check subset has no interIsoFoam): from the whole release beside
# the tarball, OpenFOAM-<version>.tar.xz
release="$(dirname "$tarball")/OpenFOAM-$version.tar.xz"
for dir in $(sed -n 's|.*$(WM_PROJECT_DIR)/\(applications/solvers/[^ ]*\).*|\1|p' \
    $makeOptions | sort -u)
do
    [ -d "$tree/$dir" ] && continue
    [ -f "$release" ] || fail "$version has no $dir, and $release is not there to take it from"
    tar -xJf "$release" -C "$tree" --strip-components=1 "OpenFOAM-$version/$dir" \
        || fail "cannot unpack $dir from $release"
done

# inOpenFOAM SCRIPT: run SCRIPT in a shell with that OpenFOAM's environment
# and nothing of the host's OpenFOAM (OpenFOAM's etc/bashrc reads the
# positional parameters as settings: none are passed to it)
inOpenFOAM()
{
    env -i HOME="$HOME" PATH=/usr/local/bin:/usr/bin:/bin CI="${CI:-}" \
        bash -c 'script=$1; set --; set +u
                 . "$0/etc/bashrc" || exit 1
                 eval "$script"' "$tree" "$1"
}

inOpenFOAM '[ -x "$WM_PROJECT_DIR/platforms/tools/linux64Gcc/wmkdepend" ] \
    || "$WM_DIR/src/Allmake" > /dev/null' \
    || fail "building wmake's tools of $version failed"

# The lnInclude folders: every one of src for the whole release (OpenFOAM's
# headers include other libraries' headers), else those the project
# includes that the tree lacks
if [ -d "$tree/applications/utilities" ] && [ ! -f "$tree/.lnInclude" ]
then
    inOpenFOAM 'wmakeLnIncludeAll "$WM_PROJECT_DIR/src"' > /dev/null 2>&1 \
        || fail "wmakeLnIncludeAll failed in $tree/src"
    touch "$tree/.lnInclude"
fi
for dir in OpenFOAM OSspecific/POSIX \
    $(sed -n 's|.*-I$(LIB_SRC)/\([^ ]*\)/lnInclude.*|\1|p' $makeOptions | sort -u)
do
    [ -d "$tree/src/$dir/lnInclude" ] && continue
    [ -d "$tree/src/$dir" ] || fail "$version has no src/$dir"
    inOpenFOAM "wmakeLnInclude -u '$tree/src/$dir'" > /dev/null 2>&1 \
        || fail "wmakeLnInclude src/$dir failed"
done

# --- A copy of the OpenFOAM side (its objects go beside its sources) --------
rm -rf "$work/foam-fmi-bridge" "$work/platforms"
cp -r "$top/foam-fmi-bridge" "$work/" || fail "cannot copy foam-fmi-bridge"
find "$work/foam-fmi-bridge" \( -name 'linux64*' -path '*/Make/*' -o -name lnInclude \) \
    -prune -exec rm -rf {} +

# --- Compile -----------------------------------------------------------------
log="$work/log.Allwmake"
inOpenFOAM '. "'"$top"'/etc/bashrc"
    [ "$FOAMFMI_OPENFOAM" = own ] || { echo "etc/bashrc did not keep '"$version"': FOAMFMI_OPENFOAM=$FOAMFMI_OPENFOAM"; exit 1; }
    export FOAM_USER_LIBBIN="'"$work"'/platforms/lib" FOAM_USER_APPBIN="'"$work"'/platforms/bin"
    export FOAMFMI_ALIAS_SAFE_SOLVERS=yes WM_NCOMPPROCS=$(nproc)
    export FOAM_EXTRA_CXXFLAGS="-O0 -Wsuggest-override"
    echo "OpenFOAM api $FOAM_API in $WM_PROJECT_DIR"
    "'"$work"'/foam-fmi-bridge/Allwmake" objects' > "$log" 2>&1
status=$?
grep -q "OpenFOAM api $api " "$log" || { tail -n 20 "$log" 1>&2; fail "the environment is not $version's (see $log)"; }
grep -q -- "-DOPENFOAM=$api" "$log" || fail "wmake did not compile with -DOPENFOAM=$api (see $log)"

nSources=0
missing=""
for files in $(find "$work/foam-fmi-bridge" -path '*/Make/files' | sort)
do
    makeDir=${files%/Make/files}
    for src in $(sed -n 's/^\([^ =$]*\.C\)[ \t]*$/\1/p' "$files")
    do
        nSources=$((nSources + 1))
        [ -f "$makeDir/Make/linux64GccDPInt32Opt/${src%.C}.o" ] \
            || missing="$missing ${makeDir#$work/}/$src"
    done
done
if [ "$status" -ne 0 ] || [ -n "$missing" ]
then
    grep -E "error|Error" -A3 "$log" | head -n 40 1>&2
    fail "not compiled against $version:${missing:- (Allwmake exit $status)} (see $log)"
fi
[ "$nSources" -ge 20 ] || fail "only $nSources sources found under foam-fmi-bridge"

# Warnings located in the project's files (OpenFOAM's own headers lack
# override in places: theirs are not ours to fix)
ownWarnings=$(grep -E ": warning: " "$log" | grep -v "^$tree/" | sort -u)
if [ -n "$ownWarnings" ]
then
    echo "$ownWarnings" 1>&2
    fail "warnings in the project's sources against $version (see $log)"
fi
pass "$nSources sources in $(find "$work/foam-fmi-bridge" -path '*/Make/files' | wc -l)" \
     "Make folders compile against $version with -Wsuggest-override, no warning of ours"

# --- A missing OpenFOAM library is named before wmake starts -----------------
fakeLib="$work/fakeLibbin"
rm -rf "$fakeLib"
mkdir -p "$fakeLib"
for lib in finiteVolume meshTools rigidBodyDynamics sixDoFRigidBodyMotion \
    forces dynamicMesh fvOptions sampling dynamicFvMesh \
    incompressibleTransportModels interfaceProperties \
    immiscibleIncompressibleTwoPhaseMixture turbulenceModels \
    incompressibleTurbulenceModels waveModels topoChangerFvMesh \
    twoPhaseProperties VoFphaseTurbulentTransportModels \
    incompressibleInterPhaseTransportModels
do
    : > "$fakeLib/lib$lib.so"
done
message=$(inOpenFOAM '. "'"$top"'/etc/bashrc"
    export FOAM_LIBBIN="'"$fakeLib"'" FOAMFMI_ALIAS_SAFE_SOLVERS=yes
    export FOAM_USER_LIBBIN="'"$work"'/platforms/lib" FOAM_USER_APPBIN="'"$work"'/platforms/bin"
    "'"$work"'/foam-fmi-bridge/Allwmake"' 2>&1)
status=$?
[ "$status" -ne 0 ] || fail "Allwmake went on without liboverset.so"
echo "$message" | grep -q "overInterDyMFoamAliasSafe.*needs liboverset.so" \
    || { echo "$message" | tail -n 5 1>&2; fail "no message naming liboverset.so"; }
echo "$message" | grep -q "^wmake \|^g++ " \
    && fail "wmake ran before the missing library was reported"
pass "an OpenFOAM without liboverset.so: $(echo "$message" | head -n 1)"

echo "$testName: done in $((SECONDS - start)) s"
