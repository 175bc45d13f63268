# Runs `caustics-bench figures` at 64x48 with 32^2 maps and checks that it writes the 14 PFM images of
# Figures 10 and 12 (8 rays-per-texel settings, 6 depths), each with the PFM header and 64 x 48 x 3
# floats; where python3-matplotlib is installed, scripts/render_figure_rows.py --bench tiles them.
file(REMOVE_RECURSE "${OUT}")
include("${CMAKE_CURRENT_LIST_DIR}/run_bench.cmake")
run_bench(figures --scene builtin --width 64 --height 48 --map-size 32 --validation --out "${OUT}/frames")
foreach(name rays_0.25 rays_0.5 rays_0.75 rays_1 rays_2 rays_4 rays_8 rays_25 depth_1 depth_2 depth_3 depth_4
             depth_8 depth_16)
  set(path "${OUT}/frames/${name}.pfm")
  if(NOT EXISTS "${path}")
    message(FATAL_ERROR "${path} was not written")
  endif()
  file(SIZE "${path}" bytes)
  # "PF\n64 48\n-1.0\n" is 14 bytes, then 64 x 48 x 3 floats.
  math(EXPR want "14 + 64 * 48 * 3 * 4")
  if(NOT bytes EQUAL want)
    message(FATAL_ERROR "${path} has ${bytes} bytes, want ${want}")
  endif()
endforeach()
if(EXISTS /usr/bin/python3)
  execute_process(COMMAND /usr/bin/python3 -c "import matplotlib" RESULT_VARIABLE hasMatplotlib OUTPUT_QUIET ERROR_QUIET)
  if(hasMatplotlib EQUAL 0)
    execute_process(COMMAND /usr/bin/python3 "${SCRIPT}" --bench "${BENCH}" --scene builtin --width 64 --height 48
                            --map-resolution 32 --out "${OUT}" RESULT_VARIABLE prc ERROR_VARIABLE perr)
    if(NOT prc EQUAL 0 OR NOT EXISTS "${OUT}/figure10_rays_per_texel.png" OR NOT EXISTS "${OUT}/figure12_depth.png")
      message(FATAL_ERROR "render_figure_rows.py --bench failed (${prc}): ${perr}")
    endif()
  endif()
endif()
