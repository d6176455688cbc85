#!/usr/bin/env bash
# No file in ui/ outside ui/panels/rtw/ names an RTW publication key: the keys are the quoted
# names between "BEGIN RTW KEYS" and "END RTW KEYS" in renderer/core/Renderer.h (a pattern
# such as "moment.<c>.<level>" counts by its prefix "moment."). A technique-independent part
# of the UI learns what to show from the declarations (TechniqueInfo), never from a name.
# usage: ui_names_no_rtw_key.sh <repository root>
set -euo pipefail
root=$1
header=$root/renderer/core/Renderer.h
mapfile -t keys < <(sed -n '/BEGIN RTW KEYS/,/END RTW KEYS/p' "$header" |
  grep -o '"[^"]*"' | tr -d '"' | sed 's/<.*//' | sort -u)
if (( ${#keys[@]} < 20 )); then
  echo "FAIL: found only ${#keys[@]} RTW keys between the markers in $header"
  exit 1
fi
echo "${#keys[@]} RTW keys from $header"
fail=0
found_in_rtw=0
for key in "${keys[@]}"; do
  # Exact keys are matched as a whole string literal; prefixes ("moment.") as a literal's start.
  if [[ $key == *. ]]; then pattern="\"$key"; else pattern="\"$key\""; fi
  hits=$(grep -rnF --include='*.cpp' --include='*.h' -- "$pattern" "$root/ui" |
    grep -v "^$root/ui/panels/rtw/" || true)
  if [[ -n $hits ]]; then
    echo "FAIL: RTW key $pattern named outside ui/panels/rtw/:"
    echo "$hits"
    fail=1
  fi
  if grep -rqF -- "$pattern" "$root/ui/panels/rtw"; then found_in_rtw=$((found_in_rtw + 1)); fi
done
# The search itself works: the RTW panels do name their keys.
if (( found_in_rtw < 10 )); then
  echo "FAIL: only $found_in_rtw RTW keys found in ui/panels/rtw/ (is the search broken?)"
  fail=1
fi
(( fail == 0 )) && echo "PASS: $found_in_rtw of ${#keys[@]} RTW keys named, all inside ui/panels/rtw/"
exit $fail
