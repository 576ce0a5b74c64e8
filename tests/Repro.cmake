# Quick-scale reproductions (label `repro`): every experiment runs at --scale quick, then
# `granrepro check` compares it with the papers' claims. Experiments are found from
# experiments/*.toml, so a new experiment is tested without editing this file.
set(REPRO_OUT ${CMAKE_BINARY_DIR}/repro-out)
file(GLOB _repro_experiments CONFIGURE_DEPENDS ${CMAKE_SOURCE_DIR}/experiments/*.toml)
foreach(_file ${_repro_experiments})
  get_filename_component(_name ${_file} NAME_WE)
  add_test(NAME repro.${_name}.run
           COMMAND granrepro ${_name} --scale quick --quiet --threads 2 --out ${REPRO_OUT})
  set_tests_properties(repro.${_name}.run PROPERTIES LABELS repro FIXTURES_SETUP repro_${_name} TIMEOUT 1800)
  add_test(NAME repro.${_name}.check COMMAND granrepro check ${_name} --out ${REPRO_OUT})
  set_tests_properties(repro.${_name}.check PROPERTIES LABELS repro FIXTURES_REQUIRED repro_${_name})
endforeach()
