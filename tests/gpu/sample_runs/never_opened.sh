#!/usr/bin/env bash
# never_opened.sh SAMPLE FIELD: the sample on a glTF whose FIELD ("buffers" or "images") URI leads out of
# the model's folder to a FIFO. Opening a FIFO for reading blocks until a writer comes, so a sample that
# opened it would hang: `timeout` ends it with 124 and the test fails. Passes when the sample refuses the
# file at once (non-zero exit) naming the URI, where it leads and the asset root (docs/viewer.md,
# "Untrusted glTF").
set -u
sample=$1; field=$2
dir=$(mktemp -d); trap 'rm -rf "$dir"' EXIT
mkdir "$dir/model"
mkfifo "$dir/outside.bin"
if [ "$field" = images ]; then
  uris='"buffers": [{"byteLength": 4, "uri": "data:application/octet-stream;base64,AAAAAA=="}], "images": [{"uri": "../outside.bin"}]'
else
  uris='"buffers": [{"byteLength": 4, "uri": "../outside.bin"}]'
fi
printf '{"asset": {"version": "2.0"}, "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}], %s}\n' "$uris" \
  > "$dir/model/escape.gltf"
output=$(timeout 60 "$sample" --scene "$dir/model/escape.gltf" 2>&1); status=$?
printf '%s\n' "$output"
echo "never_opened: exit status $status"
if [ "$status" -eq 124 ]; then echo "never_opened: FAIL: the sample blocked opening the FIFO outside its folder"; exit 1; fi
if [ "$status" -eq 0 ]; then echo "never_opened: FAIL: expected a refusal"; exit 1; fi
expected="$field\\[0\\]\\.uri '\\.\\./outside\\.bin' resolves to '.*/outside\\.bin', outside the asset root '.*/model'"
printf '%s\n' "$output" | grep -Eq -- "$expected" || { echo "never_opened: FAIL: output lacks /$expected/"; exit 1; }
echo "never_opened: PASS"
