#!/bin/sh
# Wall time of commands that should not pay for pint, typst or matplotlib imports.
cd "$(dirname "$0")/.." || exit 1
exgen=.venv/bin/exgen
for args in "--version" "list" "show belts.flat_belt_power --seed 1"; do
    start=$(date +%s%N)
    for _ in 1 2 3 4 5; do $exgen $args >/dev/null 2>&1; done
    end=$(date +%s%N)
    echo "exgen $args: $(( (end - start) / 5000000 )) ms (mean of 5)"
done
.venv/bin/python -X importtime -c "import exgen.cli" 2>&1 | sort -t'|' -k2 -n | tail -3
