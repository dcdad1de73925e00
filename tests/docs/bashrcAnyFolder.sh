#!/bin/bash
# etc/bashrc sourced from any folder sets the project's environment: run in
# a clean environment (env -i) from /tmp by its absolute path, through a
# symbolic link to the project, by a relative path from a subfolder, twice
# in one shell, and in Debian's POSIX sh (dash), which cannot tell a sourced
# file its path: from the project's folder it works, elsewhere it is refused
# with a message, never set to another folder.
#
# Usage: bashrcAnyFolder.sh PROJECT
set -u
project=$(cd "$1" && pwd -P)
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
ln -s "$project" "$scratch/link"
failures=0

# The environment a shell gets: one NAME=value a line
environment() # <shell> <folder> <commands>
{
    env -i HOME="$HOME" PATH=/usr/bin:/bin "$1" -c "cd '$2' && $3"' && printf "FOAMFMI_DIR=%s\nFOAMFMI_FMU_DIR=%s\nPATH=%s\nPYTHONPATH=%s\nfmusim=%s\n" "$FOAMFMI_DIR" "$FOAMFMI_FMU_DIR" "$PATH" "$PYTHONPATH" "$(command -v fmusim)"' 2>&1
}

expect() # <what> <output> <line that must be in it>
{
    if ! grep -qxF -- "$3" <<<"$2"
    then
        echo "FAIL $1: no line '$3' in:"
        sed 's/^/    /' <<<"$2"
        failures=$((failures + 1))
    fi
}

check() # <what> <output>
{
    expect "$1" "$2" "FOAMFMI_DIR=$project"
    expect "$1" "$2" "FOAMFMI_FMU_DIR=$project/build/fmus"
    expect "$1" "$2" "fmusim=$project/build/bin/fmusim"
    local path pythonpath
    path=$(sed -n 's/^PATH=//p' <<<"$2")
    pythonpath=$(sed -n 's/^PYTHONPATH=//p' <<<"$2")
    for dir in "$project/build/bin" "$project/bin"
    do
        if [ "$(tr : '\n' <<<"$path" | grep -cxF "$dir")" != 1 ]
        then
            echo "FAIL $1: $dir not once on PATH: $path"
            failures=$((failures + 1))
        fi
    done
    if [ "$(tr : '\n' <<<"$pythonpath" | grep -cxF "$project/python")" != 1 ]
    then
        echo "FAIL $1: $project/python not once on PYTHONPATH: $pythonpath"
        failures=$((failures + 1))
    fi
    echo "checked $1"
}

check "bash, from /tmp, absolute path" \
    "$(environment bash /tmp ". '$project/etc/bashrc'")"
check "bash, from /tmp, through a link" \
    "$(environment bash /tmp ". '$scratch/link/etc/bashrc'")"
check "bash, from tests/, relative path" \
    "$(environment bash "$project/tests" ". ../etc/bashrc")"
check "bash, sourced twice" \
    "$(environment bash /tmp ". '$project/etc/bashrc' && . '$project/etc/bashrc'")"
check "sh, from the project's folder" \
    "$(environment sh "$project" ". etc/bashrc")"
if command -v zsh > /dev/null
then
    check "zsh, from /tmp" "$(environment zsh /tmp ". '$project/etc/bashrc'")"
fi

# dash elsewhere: refused, rc 1, with the message
out=$(env -i PATH=/usr/bin:/bin sh -c "cd /tmp && . '$project/etc/bashrc'; echo rc=\$? dir=\${FOAMFMI_DIR:-unset}" 2>&1)
expect "sh, from /tmp" "$out" "rc=1 dir=unset"
if ! grep -qF "source it from bash or zsh, or from the project's folder" <<<"$out"
then
    echo "FAIL sh, from /tmp: no message naming what to do: $out"
    failures=$((failures + 1))
fi
echo "checked sh, from /tmp (refused)"

echo "$failures failures"
[ "$failures" = 0 ]
