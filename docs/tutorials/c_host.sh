#!/bin/sh
# Tutorial "Embedding the engine in a C host": runs the C99 example host
# (plugin_host/example/example_host.c, built as build/bin/eoir_example_host)
# and keeps what it prints in OUT/c_host_output.txt (OUT defaults to
# docs/tutorials/results):
#   sh docs/tutorials/c_host.sh [OUT]
set -eu
here=$(cd "$(dirname "$0")" && pwd)
out=${1:-$here/results}
host=${EOIR_EXAMPLE_HOST:-$here/../../build/bin/eoir_example_host}
mkdir -p "$out"
"$host" > "$out/c_host_output.txt"
grep -q '^EOIR Sensor Optics | Ensquared Energy | ' "$out/c_host_output.txt"
grep -q '^access: [0-9]* intervals with SNR >= 6' "$out/c_host_output.txt"
