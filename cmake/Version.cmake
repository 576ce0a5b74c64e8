# The code version stamped into every output file: git's description of the source tree,
# regenerated at every build so a rebuilt binary never reports a stale version.
set(GRANREPRO_VERSION_CPP ${CMAKE_BINARY_DIR}/generated/version.cpp)
add_custom_target(granrepro_version
  COMMAND ${CMAKE_COMMAND} -DSRC=${CMAKE_SOURCE_DIR} -DOUT=${GRANREPRO_VERSION_CPP}
          -DPROJECT_VERSION=${PROJECT_VERSION} -P ${CMAKE_SOURCE_DIR}/cmake/WriteVersion.cmake
  BYPRODUCTS ${GRANREPRO_VERSION_CPP}
  COMMENT "Stamping code version")
