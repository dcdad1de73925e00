#!/bin/bash
# Check that the project's C and C++ outside foam-fmi-bridge/ (OpenFOAM's
# style), fmu/include/ (the FMI 2.0 declarations) and third_party/ folders
# (files of others, copied unchanged) is formatted by the
# root .clang-format. Prints the files that are not; fix them with
#   clang-format -i <file>
set -eu -o pipefail
cd "${0%/*}/../.."

mapfile -t files < <(git ls-files -- '*.c' '*.h' '*.cpp' '*.hpp' \
    ':!:foam-fmi-bridge/**' ':!:fmu/include/**' ':!:**/third_party/**')
if [ "${#files[@]}" -eq 0 ]; then
    echo "checkFormat: no source files found (not a git checkout?)" >&2
    exit 1
fi

unformatted=()
for f in "${files[@]}"; do
    if ! clang-format --dry-run -Werror "$f" >/dev/null 2>&1; then
        unformatted+=("$f")
    fi
done

if [ "${#unformatted[@]}" -gt 0 ]; then
    echo "checkFormat: ${#unformatted[@]} of ${#files[@]} files differ from .clang-format:" >&2
    printf '  %s\n' "${unformatted[@]}" >&2
    echo "fix with: clang-format -i <file>" >&2
    exit 1
fi
echo "checkFormat: ${#files[@]} files formatted"
