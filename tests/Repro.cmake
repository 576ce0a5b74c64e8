# Quick-scale reproductions (label `repro`): every experiment runs at --scale quick, then
# `granrepro check` compares it with the papers' claims, and `granrepro plot --strict` renders its
# figures again and fails on any gnuplot warning (naming the figure and its log). Experiments are
# found from experiments/*.toml, so a new experiment is tested without editing this file.
set(REPRO_OUT ${CMAKE_BINARY_DIR}/repro-out)
file(GLOB _repro_experiments CONFIGURE_DEPENDS ${CMAKE_SOURCE_DIR}/experiments/*.toml)
foreach(_file ${_repro_experiments})
  get_filename_component(_name ${_file} NAME_WE)
  # The run passes when it completes (exit 0, or 1 for failing claims): judging the claims is
  # the .check test's job, and the figures are still rendered and checked (exit 4, a figure not
  # drawn, fails it). The output folder goes in as an argument, not into the shell's text.
  add_test(NAME repro.${_name}.run
           COMMAND sh -c "\"$1\" ${_name} --scale quick --quiet --threads 2 --out \"$2\"; [ $? -le 1 ]"
                   sh $<TARGET_FILE:granrepro> ${REPRO_OUT})
  set_tests_properties(repro.${_name}.run PROPERTIES LABELS repro FIXTURES_SETUP repro_${_name} TIMEOUT 1800)
  add_test(NAME repro.${_name}.check COMMAND granrepro check ${_name} --out ${REPRO_OUT})
  set_tests_properties(repro.${_name}.check PROPERTIES LABELS repro FIXTURES_REQUIRED repro_${_name})
  # `verify` on the fresh quick results (stored points): the cheapest point rerun bit for bit and
  # the scalars rebuilt from it and the stored others (issue 29 item 2).
  add_test(NAME repro.${_name}.verify COMMAND granrepro verify ${_name} --out ${REPRO_OUT})
  set_tests_properties(repro.${_name}.verify PROPERTIES LABELS repro FIXTURES_REQUIRED repro_${_name} TIMEOUT 600)
  add_test(NAME repro.${_name}.figures COMMAND granrepro plot ${_name} --strict --out ${REPRO_OUT})
  set_tests_properties(repro.${_name}.figures PROPERTIES LABELS repro FIXTURES_REQUIRED repro_${_name}
                       TIMEOUT 600)
endforeach()

# The committed paper-scale results (paper_figures/<experiment>/summary.json) re-judged against
# expected/: a change of a claim that the committed numbers no longer satisfy fails here. Until
# paper_figures/ holds results of any experiment (scripts/paper_figures.sh writes them), the
# missing ones are listed but do not fail; once some are committed, every experiment must be.
file(GLOB _committed CONFIGURE_DEPENDS ${CMAKE_SOURCE_DIR}/paper_figures/*/summary.json)
if(_committed)
  set(_missing_ok "")
else()
  set(_missing_ok "--missing-ok")
endif()
add_test(NAME paper_figures.check
         COMMAND granrepro check --all ${_missing_ok} --out ${CMAKE_SOURCE_DIR}/paper_figures)
set_tests_properties(paper_figures.check PROPERTIES LABELS repro)

# paper_figures/ comes from one physics: the committed experiments' physics hashes must agree
# (results that all predate the hashes pass with a note).
add_test(NAME paper_figures.physics COMMAND bash ${CMAKE_SOURCE_DIR}/tests/repro/physics_hashes.sh ${CMAKE_SOURCE_DIR}/paper_figures)
set_tests_properties(paper_figures.physics PROPERTIES LABELS repro)

# One cheap stored point of each committed paper-scale experiment rerun (`verify --point-only`):
# bit for bit at the recorded code version, value by value at another. Results committed before
# point storage pass only as "unverifiable: results written before point storage"
# (tests/repro/verify_committed.sh).
foreach(_summary ${_committed})
  get_filename_component(_dir ${_summary} DIRECTORY)
  get_filename_component(_name ${_dir} NAME)
  add_test(NAME paper_figures.verify.${_name}
           COMMAND bash ${CMAKE_SOURCE_DIR}/tests/repro/verify_committed.sh $<TARGET_FILE:granrepro>
                   ${CMAKE_SOURCE_DIR}/paper_figures ${_name})
  set_tests_properties(paper_figures.verify.${_name} PROPERTIES LABELS repro TIMEOUT 1800)
endforeach()

# Every claim judged at quick scale holds for seeds 1-5, not only for the default seed (issue 20):
# scripts/seed_pass_rates.sh --strict reruns the quick scale five times and prints each claim's
# pass rate (about five quick runs).
add_test(NAME repro.seed_pass_rates
         COMMAND ${CMAKE_COMMAND} -E env GRANREPRO=$<TARGET_FILE:granrepro> OUT=${CMAKE_BINARY_DIR}/seeds-out
                 bash ${CMAKE_SOURCE_DIR}/scripts/seed_pass_rates.sh --strict 5)
set_tests_properties(repro.seed_pass_rates PROPERTIES LABELS repro TIMEOUT 1800)
