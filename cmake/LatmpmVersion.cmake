# The version string recorded in every output file: project version + git hash (+dirty).
# Regenerated at every build; the file is rewritten only when the string changes.
set(LATMPM_VERSION_CPP ${PROJECT_BINARY_DIR}/generated/version.cpp)
add_custom_target(latmpm_version_file
  COMMAND ${CMAKE_COMMAND} -DSOURCE_DIR=${PROJECT_SOURCE_DIR} -DOUTPUT=${LATMPM_VERSION_CPP}
          -DPROJECT_VERSION=${PROJECT_VERSION} -P ${PROJECT_SOURCE_DIR}/cmake/WriteVersion.cmake
  BYPRODUCTS ${LATMPM_VERSION_CPP}
  COMMENT "" VERBATIM)
