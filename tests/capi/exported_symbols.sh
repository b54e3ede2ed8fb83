#!/bin/sh
# Only eoir_* symbols may be exported by the engine library (house rule 6).
lib="$1"
bad=$(nm -D --defined-only "$lib" | awk '$2 != "A" {print $3}' | grep -v '^eoir_' || true)
if [ -n "$bad" ]; then
  echo "non-eoir symbols exported by $lib:"; echo "$bad"; exit 1
fi
count=$(nm -D --defined-only "$lib" | grep -c ' T eoir_')
echo "$count eoir_* functions exported, nothing else"
[ "$count" -gt 30 ]
