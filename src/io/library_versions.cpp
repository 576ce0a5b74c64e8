#include <fftw3.h>
#include <gsl/gsl_version.h>
#include <hdf5.h>

#include "core/provenance.hpp"

namespace granrepro {

std::vector<std::pair<std::string, std::string>> library_versions() {
#if defined(__clang__)
    const std::string compiler = std::string("Clang ") + __clang_version__;
#elif defined(__GNUC__)
    const std::string compiler = std::string("GCC ") + __VERSION__;
#else
    const std::string compiler = "unknown";
#endif
    unsigned major = 0, minor = 0, release = 0;
    H5get_libversion(&major, &minor, &release);
    return {{"compiler", compiler},
            {"hdf5", std::to_string(major) + "." + std::to_string(minor) + "." + std::to_string(release)},
            {"fftw", fftw_version},
            {"gsl", gsl_version}};
}

} // namespace granrepro
