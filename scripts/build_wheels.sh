#!/usr/bin/env bash
# Build the release artefacts: the sdist, and from it one manylinux wheel
# (abi3: CPython 3.11 and newer) linked against an old glibc with zig, then
# check the wheel's platform tag with auditwheel. Used by .ci/run.
#
#   scripts/build_wheels.sh [--out DIR] [--compatibility TAG]
#
#   --out DIR            where the sdist and the wheel go (default: dist)
#   --compatibility TAG  manylinux tag to build for (default: manylinux_2_17,
#                        the same as manylinux2014); at most manylinux_2_28
#
# Needs cargo (Rust) and, in the Python that runs the script ($PYTHON,
# default python3), maturin, ziglang and auditwheel:
#
#   python3 -m pip install "maturin>=1.5,<2" ziglang auditwheel
#
# No container is needed: zig links against the chosen glibc version.
# Compiled dependencies are kept in $CARGO_TARGET_DIR (default: target/ of
# the repository), so a second run only recompiles thermobear itself.
# The sdist itself builds with Rust alone (pip install thermobear-*.tar.gz).
set -euo pipefail
cd "$(dirname "$0")/.."
root=$PWD

out=dist
compatibility=manylinux_2_17
max_glibc_minor=28 # the newest glibc the wheel may need: manylinux_2_28
while [ $# -gt 0 ]; do
    case "$1" in
    --out) out=${2:?--out needs a directory}; shift 2 ;;
    --compatibility) compatibility=${2:?--compatibility needs a tag}; shift 2 ;;
    -h | --help) sed -n '2,20p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    *) echo "build_wheels.sh: unknown argument '$1' (see --help)" >&2; exit 2 ;;
    esac
done
case "$compatibility" in
manylinux2014) ;;
manylinux_2_[0-9] | manylinux_2_[0-9][0-9])
    if [ "${compatibility#manylinux_2_}" -gt "$max_glibc_minor" ]; then
        echo "build_wheels.sh: $compatibility is newer than manylinux_2_$max_glibc_minor" >&2
        exit 2
    fi
    ;;
*) echo "build_wheels.sh: --compatibility must be a manylinux tag, got '$compatibility'" >&2; exit 2 ;;
esac

python=${PYTHON:-python3}
if ! "$python" -c "import auditwheel, maturin, ziglang" 2>/dev/null; then
    echo "build_wheels.sh: $python lacks maturin, ziglang or auditwheel; install them with" >&2
    echo "  $python -m pip install \"maturin>=1.5,<2\" ziglang auditwheel" >&2
    exit 2
fi
# The tools' scripts directory first on PATH: maturin and auditwheel, and the
# python3 through which maturin runs zig (python3 -m ziglang).
scripts=$("$python" -c 'import sysconfig; print(sysconfig.get_path("scripts"))')
export PATH="$scripts:$PATH"
export CARGO_TARGET_DIR=${CARGO_TARGET_DIR:-$root/target}

mkdir -p "$out"
out=$(cd "$out" && pwd)
stage=$(mktemp -d)
trap 'rm -rf "$stage"' EXIT

echo "== sdist"
maturin sdist --out "$stage/sdist"
sdist=$(ls "$stage"/sdist/thermobear-*.tar.gz)

echo "== $compatibility wheel from the sdist, linked with zig"
tar -xzf "$sdist" -C "$stage"
src=$(ls -d "$stage"/thermobear-*/)
(cd "$src" && maturin build --release --locked --zig --compatibility "$compatibility" \
    --out "$stage/wheel")
wheel=$(ls "$stage"/wheel/thermobear-*.whl)

echo "== auditwheel show"
auditwheel show "$wheel" | tee "$stage/auditwheel.txt"
# auditwheel's verdict, e.g. 'is consistent with the following platform tag:
# "manylinux_2_17_x86_64"' (the text is wrapped, hence the whole-file match).
"$python" - "$stage/auditwheel.txt" "$wheel" "$max_glibc_minor" <<'PY'
import re
import sys
from pathlib import Path

report, wheel, max_minor = Path(sys.argv[1]).read_text(), Path(sys.argv[2]).name, int(sys.argv[3])
found = re.search(r"following\s+platform\s+tag:\s*\"(manylinux_(\d+)_(\d+)_(\w+))\"", report)
if found is None:
    sys.exit(f"auditwheel reports no manylinux tag for {wheel}")
tag, major, minor = found.group(1), int(found.group(2)), int(found.group(3))
if (major, minor) > (2, max_minor):
    sys.exit(f"{wheel} needs glibc {major}.{minor}: {tag} is newer than manylinux_2_{max_minor}")
if tag not in wheel:
    sys.exit(f"{wheel} is not tagged {tag}, the tag auditwheel finds")
if "-abi3-" not in wheel:
    sys.exit(f"{wheel} is not an abi3 wheel")
print(f"auditwheel: {wheel} is {tag} (glibc {major}.{minor} or newer), abi3")
PY

mv "$sdist" "$wheel" "$out"/
echo "== built"
ls -l "$out/$(basename "$sdist")" "$out/$(basename "$wheel")"
