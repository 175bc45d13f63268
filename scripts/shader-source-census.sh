#!/usr/bin/env bash
# Counts the shader lines that exist in one dialect only (docs/shaders.md, "Single source"): HLSL that no
# CI tool compiles (the D3D12 twins and shims) and GLSL compiled for Vulkan alone. Shared-dialect bodies
# (passes/*/shaders/*.h, shaders/common/) are compiled as GLSL, HLSL and C++ and are not counted.
set -euo pipefail
cd "$(dirname "$0")/.."
hlsl=$( { find shaders/d3d12 \( -name '*.hlsl' -o -name '*.hlsli' -o -name '*.h' \) -not -path '*/include/*' -print; ls passes/*/shaders/*.hlsl passes/*/shaders/*.hlsli 2>/dev/null || true; } | sort -u)
glsl=$( { find shaders/vulkan -type f -print; ls passes/*/shaders/* 2>/dev/null | grep -E '\.(comp|vert|frag|rgen|rchit|rmiss|rahit|rint|glsl)$' || true; } | sort -u)
echo "HLSL lines no CI tool compiles: $(cat $hlsl | wc -l) in $(echo "$hlsl" | wc -l) files"
echo "GLSL-only lines:                $(cat $glsl | wc -l) in $(echo "$glsl" | wc -l) files"
