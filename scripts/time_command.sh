#!/usr/bin/env bash
# A compiler and linker launcher (scripts/build_profile.sh) that runs the command it is given and appends its CPU
# and wall seconds, what it made and whether it compiled or linked, to $EOMGEN_TIMES_FILE (tab-separated).
out=""
prev=""
for a in "$@"; do
  [[ $prev == -o ]] && out=$a
  prev=$a
done
kind=link
for a in "$@"; do [[ $a == -c ]] && kind=compile; done
start=$(date +%s.%N)
"$@"
rc=$?
end=$(date +%s.%N)
# `times`' second line: the user and system time of this shell's finished children, as 1m2.345s.
tmp=$(mktemp)
times > "$tmp"
read -r user sys < <(sed -n 2p "$tmp")
rm -f "$tmp"
to_s() { awk -v t="$1" 'BEGIN { split(t, p, "m"); sub("s", "", p[2]); printf "%.2f", p[1] * 60 + p[2] }'; }
printf '%s\t%s\t%s\t%s\n' "$(awk -v u="$(to_s "$user")" -v s="$(to_s "$sys")" 'BEGIN { printf "%.2f", u + s }')" \
  "$(awk -v a="$start" -v b="$end" 'BEGIN { printf "%.2f", b - a }')" "$kind" "$out" >> "${EOMGEN_TIMES_FILE:?}"
exit $rc
