#!/bin/sh
# A physical trial whose motor signals are not numbers (mpos0 blanked in its first data row) is
# refused by raven_calibrate, naming the file, before any replay.
#   no_motor_signals.sh RAVEN_CALIBRATE PAPER_2ARM_DIR WORK_DIR
set -eu
calibrate="$1" data="$2" work="$3"
if [ ! -f "$data/2arm_ci.csv" ]; then echo 'skipped: ../shared/data is absent'; exit 0; fi
mkdir -p "$work"
awk -F, -v OFS=, 'NR == 1 { for (i = 1; i <= NF; i++) if ($i == "mpos0") c = i }
                  NR == 2 { $c = "nan" } { print }' "$data/2arm_physical_2.csv" > "$work/blanked_physical_2.csv"
exec "$calibrate" score "$data/2arm_physical_1.csv" "$work/blanked_physical_2.csv" --ci "$data/2arm_ci.csv"
