// Where a result came from: the code version is stamped at build time (cmake/WriteVersion.cmake);
// the compiler and the libraries are those the binary was built with (HDF5, FFTW, GSL: the
// versions of the libraries it runs with, as they report themselves).
#pragma once
#include <string>
#include <utility>
#include <vector>

namespace granrepro {
const char* code_version();
// "sha256:<16 hex digits>" over the sources and experiment files that decide what a run computes
// (cmake/WriteVersion.cmake lists them; expected/ is not among them). Recorded in every result.
const char* physics_hash();
// {"compiler", "GCC 12.2.0"}, {"hdf5", "1.10.8"}, {"fftw", "fftw-3.3.10-sse2-avx"}, {"gsl", "2.7.1"}
std::vector<std::pair<std::string, std::string>> library_versions();
} // namespace granrepro
