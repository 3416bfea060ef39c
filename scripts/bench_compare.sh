#!/usr/bin/env bash
# Run the gear criterion benches (benches/dynamics.rs, benches/gear.rs)
# against the baseline stored in benches/baseline/ and print the change of
# every bench's mean time; exit 1 when one grew by more than the allowed
# regression.
#
# Usage: scripts/bench_compare.sh [--max-regression PCT] [--save] [--quick]
#                                 [--benches "dynamics gear"] [FILTER]
#   --max-regression PCT  fail above this mean-time increase in % (default 10)
#   --save                run the benches and store them as the new baseline
#                         (benches/baseline/), comparing nothing
#   --quick               shorter measurement (criterion --warm-up-time 1
#                         --measurement-time 2): noisier, for a quick look
#   --benches LIST        bench targets (default "dynamics gear")
#   FILTER                criterion name filter (e.g. seed_rk4)
#
# Times are wall-clock means from criterion; on a shared or loaded machine
# they move by several percent between runs, so compare on a quiet machine
# (or raise --max-regression). The baseline's machine is recorded in
# benches/baseline/MACHINE.txt; a baseline from another CPU is not a fair
# reference.
set -euo pipefail

root="$(cd "$(dirname "$0")/.." && pwd)"
max_regression=10
save=0
benches="dynamics gear"
filter=""
extra=()
while [ $# -gt 0 ]; do
    case "$1" in
        --max-regression) max_regression="$2"; shift 2 ;;
        --save) save=1; shift ;;
        --quick) extra+=(--warm-up-time 1 --measurement-time 2); shift ;;
        --benches) benches="$2"; shift 2 ;;
        -h|--help) sed -n '2,22p' "$0"; exit 0 ;;
        -*) echo "unknown option $1" >&2; exit 2 ;;
        *) filter="$1"; shift ;;
    esac
done

baseline_dir="$root/benches/baseline"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
export CRITERION_HOME="$work/criterion"
mkdir -p "$CRITERION_HOME"

bench_args=()
for b in $benches; do bench_args+=(--bench "$b"); done
run() {
    (cd "$root" && cargo bench --quiet "${bench_args[@]}" -- --noplot "${extra[@]}" "$@" ${filter:+"$filter"})
}

if [ "$save" = 1 ]; then
    run --save-baseline repo
    mkdir -p "$baseline_dir"
    (cd "$CRITERION_HOME" && find . -type d -name repo) | while read -r d; do
        rel="${d#./}"; rel="${rel%/repo}"
        mkdir -p "$baseline_dir/$rel"
        cp "$CRITERION_HOME/$d/"*.json "$baseline_dir/$rel/"
    done
    {
        echo "saved: $(date -u +%Y-%m-%dT%H:%MZ)"
        echo "commit: $(cd "$root" && git rev-parse --short HEAD 2>/dev/null || echo unknown)"
        echo "cpu: $(grep -m1 'model name' /proc/cpuinfo 2>/dev/null | cut -d: -f2- | sed 's/^ //')"
        echo "cores: $(nproc 2>/dev/null || echo ?)"
        echo "rustc: $(rustc --version)"
        echo "load average while saving: $(cut -d' ' -f1-3 /proc/loadavg 2>/dev/null || echo ?)"
    } > "$baseline_dir/MACHINE.txt"
    echo "baseline saved to $baseline_dir"
    exit 0
fi

if [ ! -d "$baseline_dir" ]; then
    echo "no baseline in $baseline_dir (run with --save first)" >&2
    exit 2
fi
# Install the stored baseline under the name "repo".
(cd "$baseline_dir" && find . -name estimates.json) | while read -r f; do
    rel="$(dirname "${f#./}")"
    mkdir -p "$CRITERION_HOME/$rel/repo"
    cp "$baseline_dir/$rel/"*.json "$CRITERION_HOME/$rel/repo/"
done
run --baseline-lenient repo

python3 - "$CRITERION_HOME" "$max_regression" <<'EOF'
import json, pathlib, sys

home, limit = pathlib.Path(sys.argv[1]), float(sys.argv[2])
rows, worst = [], None
for change in sorted(home.rglob("change/estimates.json")):
    bench = change.parent.parent
    name = json.loads((bench / "new" / "benchmark.json").read_text())["full_id"]
    new = json.loads((bench / "new" / "estimates.json").read_text())["mean"]["point_estimate"]
    base = json.loads((bench / "repo" / "estimates.json").read_text())["mean"]["point_estimate"]
    c = json.loads(change.read_text())["mean"]
    pct = 100 * c["point_estimate"]
    lo = 100 * c["confidence_interval"]["lower_bound"]
    hi = 100 * c["confidence_interval"]["upper_bound"]
    rows.append((name, base, new, pct, lo, hi))
    if worst is None or pct > worst[1]:
        worst = (name, pct)

def t(ns):
    for unit, f in (("s", 1e9), ("ms", 1e6), ("us", 1e3)):
        if ns >= f:
            return f"{ns / f:.3f} {unit}"
    return f"{ns:.1f} ns"

if not rows:
    print("no benchmark was compared (filter matched nothing, or no baseline for it)")
    sys.exit(2)
w = max(len(r[0]) for r in rows)
print(f"\n{'bench':<{w}}  {'baseline':>12}  {'now':>12}  {'change':>8}  95% CI")
for name, base, new, pct, lo, hi in rows:
    flag = "  REGRESSION" if pct > limit else ""
    print(f"{name:<{w}}  {t(base):>12}  {t(new):>12}  {pct:+7.1f}%  [{lo:+.1f}, {hi:+.1f}]{flag}")
if worst[1] > limit:
    print(f"\nFAIL: {worst[0]} is {worst[1]:+.1f}% slower (limit +{limit:g}%)")
    sys.exit(1)
print(f"\nOK: no mean time grew by more than {limit:g}%")
EOF
