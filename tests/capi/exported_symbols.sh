#!/bin/sh
# The C ABI is a promise (house rule 6): the engine library exports only
# eoir_* symbols, and every symbol of the ABI baseline (capi/abi/symbols_v1.txt)
# is still exported (new ones may be added; none may go).
lib="$1"
baseline="$2"
bad=$(nm -D --defined-only "$lib" | awk '$2 != "A" {print $3}' | grep -v '^eoir_' || true)
if [ -n "$bad" ]; then
  echo "non-eoir symbols exported by $lib:"; echo "$bad"; exit 1
fi
exported=$(nm -D --defined-only "$lib" | awk '$2 == "T" {print $3}' | sort)
missing=$(echo "$exported" | comm -13 - "$baseline")
if [ -n "$missing" ]; then
  echo "symbols of the ABI baseline no longer exported:"; echo "$missing"; exit 1
fi
count=$(echo "$exported" | wc -l)
echo "$count eoir_* functions exported, nothing else; all $(wc -l < "$baseline") baseline symbols present"
