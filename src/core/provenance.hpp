// Where a result came from: the code version is stamped at build time (cmake/WriteVersion.cmake).
#pragma once

namespace granrepro {
const char* code_version();
} // namespace granrepro
