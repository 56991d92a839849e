# Copyright 2026 the brdfbake authors.
# SPDX-License-Identifier: Apache-2.0
#
# A model family is a column (docs/architecture.md): its model kinds are
# named in its own files, and elsewhere only where a shared file chooses
# models by design. For each brdfbake_family(...) registration of
# CMakeLists.txt, every file of src/, include/ and tools/ naming one of
# its kinds (ModelKind::k<Kind>, or BakeSpec's helper for it: Glass() for
# GgxGlass, Anisotropic() for GgxAniso) must be
#   - its own: src/kernels/batch_<family>.cc, src/bake/families/<family>_tables.cc,
#     a file of the folder of each rule its registration's SOURCES names
#     (src/rules/<folder>/), or a file of the same stem as each of its
#     lanes and samplers (src/lanes/<stem>.*, src/sampling/<stem>.*);
#   - or listed below, with the reason the shared file names the kind.
# kGgx is the model every build has and every request's default: it may
# be named anywhere.
#   cmake -DSOURCE_DIR=<project> -P family_columns_test.cmake
cmake_minimum_required(VERSION 3.20)

# BakeSpec's helpers (include/brdfbake/table_spec.h) that name a kind.
set(helpers "GgxGlass|Glass" "GgxAniso|Anisotropic")
# Shared files naming a family's kinds, as file|Kind,Kind|reason.
set(shared
  "src/scene/scene.cc|*|a scene's materials choose their models (glTF extensions, TOML)"
  "src/engines/presets.cc|*|an engine's tables are those of the models it renders"
  "src/bake/table_spec.cc|Sel|a table kind of one model's lobe names that model (sel_norm)"
  "include/brdfbake/table_spec.h|GgxAniso,GgxGlass|BakeSpec's helpers for the table models' axes"
  "src/bake/texel_for.h|StudentT|the microfacet texel the ggx, beckmann and std rows share"
  "src/kernels/batch.cc|Beckmann|the rough dielectric's batch takes the ggx or beckmann NDF"
  "src/kernels/batch_glass.cc|Beckmann|the rough dielectric over the beckmann NDF"
  "src/analysis/eval.cc|GgxAniso|eval's anisotropy strength, the ggx-aniso tables' parameter"
  "src/analysis/probe.cc|GgxAniso,GgxGlass|a texel's exact value at the table models' own coordinates"
  "src/analysis/report.cc|GgxAniso,GgxGlass|the report's probe sizes and study over the table models' axes"
  "src/bake/bake.cc|GgxGlass|each ior slice's eta: the ior, or its inverse inside the medium"
  "src/io/exr.cc|GgxGlass|the rough dielectric's Fresnel factor in the tables' metadata"
  "src/io/containers.cc|GgxGlass|the rough dielectric's Fresnel factor in the tables' metadata"
  "tools/brdfbake/main.cc|GgxAniso,GgxGlass,Ellipsoid,DisneyDiffuse|the options of the models whose widths are not \
alpha = r^2 alone: ggx-aniso's and ggx-glass's from the tables' axes, the ellipsoid's material, disney-diffuse's r")

file(READ "${SOURCE_DIR}/CMakeLists.txt" cmakelists)
string(REGEX MATCHALL "\nbrdfbake_family\\([^)]*\\)" registrations "${cmakelists}")
list(LENGTH registrations count)
if(count LESS 2)
  message(FATAL_ERROR "found ${count} brdfbake_family registrations in CMakeLists.txt")
endif()
file(GLOB_RECURSE files RELATIVE "${SOURCE_DIR}" "${SOURCE_DIR}/src/*" "${SOURCE_DIR}/include/*"
     "${SOURCE_DIR}/tools/*")
set(failures "")
set(named 0)
foreach(registration IN LISTS registrations)
  string(STRIP "${registration}" registration)
  string(REGEX REPLACE "[ \t\n]+" ";" words "${registration}")
  list(GET words 0 call)
  string(REGEX REPLACE "^brdfbake_family\\(" "" family "${call}")
  # The kinds (Enumerator=name) and the sources (after SOURCES, to TESTS).
  set(kinds "")
  set(own "src/kernels/batch_${family}.cc" "src/bake/families/${family}_tables.cc")
  set(section "")
  foreach(w IN LISTS words)
    string(REGEX REPLACE "\\)$" "" w "${w}")
    if(w STREQUAL "SOURCES" OR w STREQUAL "TESTS")
      set(section "${w}")
    elseif(w MATCHES "^([A-Z][A-Za-z0-9]*)=")
      list(APPEND kinds "${CMAKE_MATCH_1}")
    elseif(section STREQUAL "SOURCES" AND w MATCHES "^rules/([^/]+)/")
      list(APPEND own "src/rules/${CMAKE_MATCH_1}/")
    elseif(section STREQUAL "SOURCES" AND w MATCHES "^((lanes|sampling)/[^.]+)\\.")
      list(APPEND own "src/${CMAKE_MATCH_1}.")
    endif()
  endforeach()
  if(NOT kinds)
    message(FATAL_ERROR "brdfbake_family(${family}): no Enumerator=name kind")
  endif()
  foreach(kind IN LISTS kinds)
    if(kind STREQUAL "Ggx")
      continue()
    endif()
    set(pattern "ModelKind::k${kind}([^A-Za-z0-9_]|$)")
    foreach(helper IN LISTS helpers)
      if(helper MATCHES "^${kind}\\|(.*)$")
        string(APPEND pattern "|[.>]${CMAKE_MATCH_1}\\(\\)")
      endif()
    endforeach()
    foreach(f IN LISTS files)
      file(STRINGS "${SOURCE_DIR}/${f}" hits REGEX "${pattern}")
      if(NOT hits)
        continue()
      endif()
      math(EXPR named "${named} + 1")
      set(ok OFF)
      foreach(prefix IN LISTS own)
        string(FIND "${f}" "${prefix}" at)
        if(at EQUAL 0)
          set(ok ON)
        endif()
      endforeach()
      foreach(entry IN LISTS shared)
        string(REPLACE "|" ";" parts "${entry}")
        list(GET parts 0 path)
        list(GET parts 1 allowed)
        string(REPLACE "," ";" allowed "${allowed}")
        if(f STREQUAL path AND (allowed STREQUAL "*" OR kind IN_LIST allowed))
          set(ok ON)
        endif()
      endforeach()
      if(NOT ok)
        string(APPEND failures "\n  ${f} names the kind ${kind} of family ${family} outside its column")
      endif()
    endforeach()
  endforeach()
endforeach()
if(named EQUAL 0)
  message(FATAL_ERROR "no file names any family's kind: the scan found nothing to check")
endif()
# Every listed exception is still needed: a shared file that stopped naming
# a kind leaves the list.
foreach(entry IN LISTS shared)
  string(REPLACE "|" ";" parts "${entry}")
  list(GET parts 0 path)
  list(GET parts 1 allowed)
  if(allowed STREQUAL "*")
    set(allowed "[A-Za-z0-9]+")
  endif()
  string(REPLACE "," ";" allowed "${allowed}")
  foreach(kind IN LISTS allowed)
    set(pattern "ModelKind::k${kind}([^A-Za-z0-9_]|$)")
    foreach(helper IN LISTS helpers)
      string(REPLACE "|" ";" hk "${helper}")
      list(GET hk 0 helper_kind)
      list(GET hk 1 name)
      if(helper_kind MATCHES "^${kind}$")
        string(APPEND pattern "|[.>]${name}\\(\\)")
      endif()
    endforeach()
    file(STRINGS "${SOURCE_DIR}/${path}" hits REGEX "${pattern}")
    if(NOT hits)
      string(APPEND failures "\n  ${path} is listed as naming ${kind} but no longer does: drop it from the list")
    endif()
  endforeach()
endforeach()
if(failures)
  message(FATAL_ERROR "a model family's kinds named outside its column:${failures}")
endif()
message(STATUS "family columns: ${count} families, ${named} (file, kind) pairs, all in their columns or listed")
