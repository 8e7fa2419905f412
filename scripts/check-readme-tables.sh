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
# Usage: scripts/check-readme-tables.sh [--fix]
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
    if diff -u --label "README.md ($name)" --label "generated ($name)" \
        "$work/$name.have" "$work/$name.want" >"$work/$name.diff"; then
        echo "check-readme-tables: $name is current"
    elif ((fix)); then
        awk -v start="<!-- $name:start -->" -v end="<!-- $name:end -->" -v file="$work/$name.want" '
            $0 == start {print; while ((getline line < file) > 0) print line; skip = 1; next}
            $0 == end {skip = 0}
            !skip {print}' "$readme" >"$work/README.md"
        cp "$work/README.md" "$readme"
        echo "check-readme-tables: $name written into README.md"
    else
        cat "$work/$name.diff" >&2
        stale=1
    fi
done
if ((stale)); then
    cat >&2 <<'EOF'
check-readme-tables: README.md's tables differ from this run's figures (above). If the change
in figures is meant (a change in src/, the compiler or QEMU), regenerate them:
    scripts/firmware.sh && scripts/check-readme-tables.sh --fix
and commit README.md; the text around the tables may need the new figures too.
EOF
fi
exit "$stale"
