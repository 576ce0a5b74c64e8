# One make-figure target per paper figure: `cmake --build build --target luding98-fig07`.
# The figure ids are read from the [[figure]] tables of experiments/*.toml, so a new figure needs
# no edit here. GRANREPRO_FIGURE_SCALE (quick|paper) and GRANREPRO_FIGURE_OUT choose the run.
set(GRANREPRO_FIGURE_SCALE "quick" CACHE STRING "scale of the figure targets (quick or paper)")
set(GRANREPRO_FIGURE_OUT "${CMAKE_BINARY_DIR}/figures" CACHE PATH "output directory of the figure targets")
file(GLOB _experiment_files CONFIGURE_DEPENDS ${CMAKE_SOURCE_DIR}/experiments/*.toml)
set(GRANREPRO_FIGURES "")
foreach(_file ${_experiment_files})
  file(STRINGS ${_file} _lines REGEX "^id *= *\"[^\"]+\"")
  foreach(_line ${_lines})
    string(REGEX REPLACE "^id *= *\"([^\"]+)\".*" "\\1" _id "${_line}")
    list(APPEND GRANREPRO_FIGURES ${_id})
    add_custom_target(${_id}
      COMMAND $<TARGET_FILE:granrepro> figure ${_id} --scale ${GRANREPRO_FIGURE_SCALE}
              --out ${GRANREPRO_FIGURE_OUT} --threads 2
      DEPENDS granrepro
      WORKING_DIRECTORY ${CMAKE_SOURCE_DIR}
      COMMENT "Reproducing ${_id} (${GRANREPRO_FIGURE_SCALE} scale) into ${GRANREPRO_FIGURE_OUT}"
      USES_TERMINAL)
  endforeach()
endforeach()
