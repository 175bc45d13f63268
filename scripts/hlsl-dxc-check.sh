#!/usr/bin/env bash
# The HLSL the D3D12 backend compiles is run through no DXC here (Debian 12 has none), so this check
# preprocesses every HLSL entry as DXC would see it (the C preprocessor with __HLSL_VERSION, the
# include path of shaders/d3d12/CMakeLists.txt, the generated binding declarations of BUILD_DIR) and
# greps the result for the constructs DXC is known to reject (docs/d3d12.md, "Constructs DXC rejects").
# Usage: scripts/hlsl-dxc-check.sh [BUILD_DIR]   (default build/; the build generates the bindings)
set -euo pipefail
cd "$(dirname "$0")/.."
build="${1:-build}"
generated="$build/generated_shaders/hlsl"
if [ ! -d "$generated" ]; then
  echo "hlsl-dxc-check: $generated missing (build first: scripts/build.sh)" >&2
  exit 2
fi
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT

# entry file, stage define (a pass's own entry is compiled once per GLSL entry beside it)
entries=()
while IFS= read -r f; do entries+=("$f|"); done < <(find shaders/d3d12 -name '*.hlsl' | sort)
for f in passes/*/shaders/*.hlsl; do
  [ -e "$f" ] || continue
  base="${f%.hlsl}"
  for glsl in "$base".*; do
    stage="${glsl##*.}"
    case "$stage" in comp|vert|frag|rgen|rmiss|rchit|rahit|rint) entries+=("$f|CAUSTICS_STAGE_${stage^^}") ;; esac
  done
done

failures=0
report() {   # rule, entry, matching lines
  echo "hlsl-dxc-check: $2: $1:" >&2
  echo "$3" | sed 's/^/    /' >&2
  failures=$((failures + 1))
}

for e in "${entries[@]}"; do
  file="${e%%|*}"
  define="${e#*|}"
  out="$tmp/expanded.hlsl"
  args=(-P -undef -D__HLSL_VERSION=2021 -I "$(dirname "$file")" -I shaders/d3d12 -I "$generated" -I shaders)
  [ -n "$define" ] && args+=(-D "$define=1")
  if ! cpp "${args[@]}" "$file" -o "$out" 2>"$tmp/cpp.log"; then
    report "does not preprocess" "$file" "$(grep -v warning "$tmp/cpp.log" | head -5)"
    continue
  fi
  name="$file${define:+ ($define)}"

  # 1. A struct as an operand of ?: (DXC: "condition/operands must be scalar, vector or matrix"): a
  #    declaration of a struct type whose initializer has a ?: outside any parentheses.
  structs="$(grep -oE '\bstruct[[:space:]]+[A-Za-z_][A-Za-z0-9_]*' "$out" | awk '{print $2}' | sort -u | paste -sd'|' -)"
  if [ -n "$structs" ]; then
    hits="$(STRUCTS="$structs" perl -ne 'if (/\b(?:$ENV{STRUCTS})\s+\w+\s*=\s*([^;]*)/) {
        my $init = $1; 1 while $init =~ s/\([^()]*\)//g; print "$.: $_" if $init =~ /\?/; }' "$out")"
    [ -n "$hits" ] && report "a struct selected with ?: (use if/else)" "$name" "$hits"
  fi
  # 2. GLSL spellings that reached the HLSL text (a shared-dialect macro missing or bypassed).
  hits="$(grep -nE '\b([iu]?vec[234]|mat[234]|texelFetch|imageStore|imageLoad|atomicAdd|atomicMax|atomicMin|atomicOr|mix|fract|inversesqrt|floatBitsToUint|uintBitsToFloat)[[:space:]]*\(|\bgl_[A-Za-z]+|\blayout[[:space:]]*\(' "$out" || true)"
  [ -n "$hits" ] && report "GLSL-only spelling" "$name" "$hits"
  # 3. A vector built from one scalar literal (HLSL has no splat constructor: use splat2/splat3 or a cast).
  hits="$(grep -nE '\b(float|uint|int)[234][[:space:]]*\([[:space:]]*-?[0-9][0-9.eE+-]*[fu]?[[:space:]]*\)' "$out" || true)"
  [ -n "$hits" ] && report "a vector constructor from one scalar" "$name" "$hits"
  # 4. A resource without an explicit register space (docs/d3d12.md: layout i -> space i).
  hits="$(grep -nE ':[[:space:]]*register[[:space:]]*\([[:space:]]*[btus][0-9]+[[:space:]]*\)' "$out" || true)"
  [ -n "$hits" ] && report "a register without its space" "$name" "$hits"
done

if [ "$failures" -gt 0 ]; then
  echo "hlsl-dxc-check: $failures problem(s) in ${#entries[@]} HLSL entries" >&2
  exit 1
fi
echo "hlsl-dxc-check: ${#entries[@]} HLSL entries preprocessed, none uses a construct DXC rejects (docs/d3d12.md)"
