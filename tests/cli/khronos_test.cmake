# Copyright 2026 the brdfbake authors.
# SPDX-License-Identifier: Apache-2.0
#
# The khronos preset as a user bakes it, at its full 1024x1024 size: run as
# `cmake -DBRDFBAKE=path -DOUT=dir -P khronos_test.cmake`. Each PNG is read
# back by OpenImageIO (oiiotool --dumpdata), and texels of each table,
# from the smooth top row to the rough bottom row and from grazing to
# normal NoV, hold `brdfbake eval`'s value at the texel's centre within
# half a pixel step (plus the preset's tolerance).

cmake_minimum_required(VERSION 3.16)

execute_process(COMMAND ${BRDFBAKE} bake --preset khronos -o ${OUT}
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "bake --preset khronos: exit ${rc}: ${err}")
endif()

# (file, bits, eval arguments, columns of eval's output compared with R, G, B)
set(tables
  "lut_ggx|8|--quantity,dfg|2,3,-1"
  "lut_charlie|8|--quantity,E,--model,charlie,--visibility,neubelt-clamped|2,2,2"
  "lut_sheen_E|16|--quantity,E,--model,charlie,--visibility,conty-kulla-clamped|2,2,2")
set(texels "0 0" "1023 0" "0 1023" "1023 1023" "5 1000" "700 300" "300 700" "512 40" "40 512")
foreach(entry ${tables})
  string(REPLACE "|" ";" parts "${entry}")
  list(GET parts 0 name)
  list(GET parts 1 bits)
  list(GET parts 2 eval_args)
  list(GET parts 3 columns)
  string(REPLACE "," ";" eval_args "${eval_args}")
  string(REPLACE "," ";" columns "${columns}")
  math(EXPR max "(1 << ${bits}) - 1")
  # The header line and the pixels wanted, out of a million.
  execute_process(COMMAND oiiotool --dumpdata ${OUT}/${name}.png
    COMMAND grep -E "png$|^ *Pixel \\(([0-9]+, 0|[0-9]+, 1023|5, 1000|700, 300|300, 700|512, 40|40, 512)\\):"
    RESULT_VARIABLE rc OUTPUT_VARIABLE dump ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "oiiotool --dumpdata ${name}.png: ${err}")
  endif()
  if(NOT dump MATCHES "1024 x 1024, 3 channel, uint${bits} png")
    message(FATAL_ERROR "${name}.png is not a 1024x1024 RGB ${bits}-bit PNG")
  endif()
  foreach(texel ${texels})
    string(REPLACE " " ";" xy "${texel}")
    list(GET xy 0 x)
    list(GET xy 1 y)
    if(NOT dump MATCHES "Pixel \\(${x}, ${y}\\): ([0-9]+) ([0-9]+) ([0-9]+) ")
      message(FATAL_ERROR "${name}.png: no pixel (${x}, ${y}) in OpenImageIO's dump")
    endif()
    set(codes ${CMAKE_MATCH_1} ${CMAKE_MATCH_2} ${CMAKE_MATCH_3})
    # The texel's centre: NoV = (x + 0.5) / 1024, r = (y + 0.5) / 1024
    # (row 0, the PNG's top row, the smooth end).
    math(EXPR nov_num "2 * ${x} + 1")
    math(EXPR r_num "2 * ${y} + 1")
    set(nov "${nov_num}/2048")
    set(r "${r_num}/2048")
    # eval takes decimal inputs: these fractions are exact in 12 digits.
    execute_process(COMMAND awk "BEGIN { printf \"%.12f %.12f\", ${nov}, ${r} }" OUTPUT_VARIABLE nr)
    string(REPLACE " " ";" nr "${nr}")
    list(GET nr 0 nov_dec)
    list(GET nr 1 r_dec)
    execute_process(COMMAND ${BRDFBAKE} eval ${eval_args} --roughness ${r_dec} --mu-o ${nov_dec}
      RESULT_VARIABLE rc OUTPUT_VARIABLE csv ERROR_VARIABLE err)
    if(NOT rc EQUAL 0)
      message(FATAL_ERROR "eval ${eval_args}: ${err}")
    endif()
    # The second line of eval's CSV output (the first is the header).
    string(REPLACE "\n" ";" lines "${csv}")
    list(GET lines 1 row)
    string(REPLACE "," ";" row "${row}")
    foreach(c 0 1 2)
      list(GET columns ${c} col)
      list(GET codes ${c} code)
      if(col LESS 0)  # lut_ggx B: E = scale + bias
        list(GET row 2 s)
        list(GET row 3 b)
        set(want "(${s} + ${b})")
      else()
        list(GET row ${col} want)
      endif()
      # |code / max - min(1, want)| <= half a step + 2e-5.
      execute_process(COMMAND awk "BEGIN { w = ${want}; if (w > 1) w = 1; d = ${code} / ${max} - w; if (d < 0) d = -d; t = 0.5 / ${max} + 2e-5; printf \"%d %.3g %.3g\", d <= t, d, t }"
        OUTPUT_VARIABLE verdict)
      string(REPLACE " " ";" verdict "${verdict}")
      list(GET verdict 0 ok)
      if(NOT ok)
        message(FATAL_ERROR "${name}.png pixel (${x}, ${y}) channel ${c}: code ${code}/${max} against eval's ${want} (off by ${verdict})")
      endif()
    endforeach()
  endforeach()
  message(STATUS "${name}.png: 9 texels match brdfbake eval")
endforeach()
