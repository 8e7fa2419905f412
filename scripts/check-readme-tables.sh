#!/usr/bin/env bash
# Checks that the README's generated tables are what the scripts print now, or with --fix
# writes them in.
#
# Each table sits in README.md between `<!-- NAME:start -->` and `<!-- NAME:end -->`:
#
#   firmware-table   the performance tables, as scripts/firmware.sh last wrote them to
#                    firmware/target/firmware-tables.md (so run scripts/firmware.sh first:
#                    QEMU runs once, and this reads what that run measured)
#   accuracy-table   the accuracy table, printed by
#                    cargo run --release --example accuracy -- --markdown
#
# A table is current when every line matches this run's, with one allowance: in the firmware
# table a figure may differ by up to 1 % of the larger of the two (`24 608` and `24 800`
# match; `591` and `603` do not), so that a rebuild which moves code by a few bytes or
# instructions is not a change to commit. A figure is a number as the tables write it,
# thousands apart (`5 815 137`), perhaps with decimals (`39.0`); everything else on the line,
# hashes (`0xdd797f7a`), versions (`1.95.0`), names and units, must match exactly, as must
# the number of lines and figures. The accuracy table comes from the host's deterministic
# render, and there any change is real: it must match exactly.
#
# Usage: scripts/check-readme-tables.sh [--fix]
#   --fix   writes this run's tables into README.md wherever they differ at all, within the
#           allowance or not (to refresh the figures on purpose)
#
# Exit status: 0 if every table is current (or was written in with --fix), 1 if one is stale,
# 2 if a source is missing.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"

fix=0
case ${1:-} in
    --fix) fix=1 ;;
    "") ;;
    *) echo "usage: scripts/check-readme-tables.sh [--fix]" >&2; exit 2 ;;
esac

readme=README.md
firmware_tables=firmware/target/firmware-tables.md
if [[ ! -f $firmware_tables ]]; then
    echo "check-readme-tables: $firmware_tables is missing; run scripts/firmware.sh first" >&2
    exit 2
fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cp "$firmware_tables" "$work/firmware-table"
cargo run --quiet --release --example accuracy -- --markdown \
    >"$work/accuracy-table"

block() { # name: the README's lines between the name's markers
    awk -v start="<!-- $1:start -->" -v end="<!-- $1:end -->" '
        $0 == end {on = 0} on {print} $0 == start {on = 1}' "$readme"
}

# The allowance for each table's figures, as a fraction of the larger figure.
declare -A tolerance=([firmware-table]=0.01 [accuracy-table]=0)

within() { # have want tolerance: 0 if the two files' lines match, figures within tolerance
    LC_ALL=C awk -v tol="$3" '
        # The line with each figure replaced by "#", and the figures in nums[1..n].
        function parse(s, nums,    out, n, word, tail) {
            out = ""; n = 0
            while (s != "") {
                if (match(s, /^[A-Za-z0-9_.]+/)) {
                    word = substr(s, 1, RLENGTH); s = substr(s, RLENGTH + 1)
                    # Thousands written apart: "5 815 137", "2 082.2".
                    if (word ~ /^[0-9][0-9]?[0-9]?$/) {
                        while (match(s, /^ [0-9][0-9][0-9]([.][0-9]+)?/)) {
                            tail = substr(s, RLENGTH + 1, 1)
                            if (tail ~ /[A-Za-z0-9_.]/) break
                            word = word substr(s, 2, RLENGTH - 1); s = substr(s, RLENGTH + 1)
                            if (word ~ /[.]/) break
                        }
                    }
                    if (word ~ /^[0-9]+([.][0-9]+)?$/) { nums[++n] = word + 0; out = out "#" }
                    else out = out word
                } else {
                    out = out substr(s, 1, 1); s = substr(s, 2)
                }
            }
            nums[0] = n
            return out
        }
        function abs(x) { return x < 0 ? -x : x }
        FILENAME == ARGV[1] { have[FNR] = $0; lines_have = FNR; next }
        {
            lines_want = FNR
            split("", h); split("", w)
            a = parse(have[FNR], h); b = parse($0, w)
            bad = (a != b || h[0] != w[0] || (tol == 0 && have[FNR] != $0))
            for (i = 1; !bad && i <= w[0]; i++) {
                big = abs(h[i]) > abs(w[i]) ? abs(h[i]) : abs(w[i])
                if (abs(h[i] - w[i]) > tol * big + 1e-9) bad = 1
                else if (h[i] != w[i]) moved++
            }
            if (bad) {
                stale = 1
                printf "  README.md: %s\n  this run:  %s\n", have[FNR], $0 > "/dev/stderr"
            }
        }
        END {
            if (lines_have != lines_want) {
                stale = 1
                printf "  README.md has %d lines, this run %d\n", lines_have, lines_want > "/dev/stderr"
            }
            if (!stale && moved) printf "(%d figure%s within %g %%)", moved, (moved > 1 ? "s" : ""), 100 * tol
            exit stale
        }' "$1" "$2"
}

stale=0
for name in firmware-table accuracy-table; do
    if [[ $(grep -cxF -- "<!-- $name:start -->" "$readme") != 1 ||
        $(grep -cxF -- "<!-- $name:end -->" "$readme") != 1 ]]; then
        echo "check-readme-tables: README.md needs one <!-- $name:start --> and one" \
            "<!-- $name:end --> line" >&2
        exit 2
    fi
    # The block holds the generated lines with one blank line either side, so that Markdown
    # sees the table apart from the comments.
    { echo; cat "$work/$name"; echo; } >"$work/$name.want"
    block "$name" >"$work/$name.have"
    if ((fix)) && ! cmp -s "$work/$name.have" "$work/$name.want"; then
        awk -v start="<!-- $name:start -->" -v end="<!-- $name:end -->" -v file="$work/$name.want" '
            $0 == start {print; while ((getline line < file) > 0) print line; skip = 1; next}
            $0 == end {skip = 0}
            !skip {print}' "$readme" >"$work/README.md"
        cp "$work/README.md" "$readme"
        echo "check-readme-tables: $name written into README.md"
    elif moved=$(within "$work/$name.have" "$work/$name.want" "${tolerance[$name]}" \
        2>"$work/$name.diff"); then
        echo "check-readme-tables: $name is current${moved:+ $moved}"
    else
        echo "check-readme-tables: $name is stale; the lines that differ:" >&2
        cat "$work/$name.diff" >&2
        stale=1
    fi
done
if ((stale)); then
    cat >&2 <<'EOF'
check-readme-tables: README.md's tables differ from this run's figures (above), beyond the
allowance. If the change in figures is meant (a change in src/, the compiler or QEMU),
regenerate them:
    scripts/firmware.sh && scripts/check-readme-tables.sh --fix
and commit README.md; the text around the tables may need the new figures too.
EOF
fi
exit "$stale"
