#include "harness/mpi_world.hpp"

#include <cstdlib>
#include <string>

#include "core/input_error.hpp"

#ifdef GRANREPRO_HAVE_MPI
#include <mpi.h>
#endif

namespace granrepro::mpi {

namespace {
int g_rank = 0, g_size = 1;
bool g_multiple = false, g_active = false;
} // namespace

void init([[maybe_unused]] int& argc, [[maybe_unused]] char**& argv) {
#ifdef GRANREPRO_HAVE_MPI
    // Only under a launcher: a plain `granrepro list` must not need an MPI runtime.
    if (!std::getenv("OMPI_COMM_WORLD_SIZE") && !std::getenv("PMI_SIZE") && !std::getenv("PMIX_RANK")) return;
    int provided = 0;
    MPI_Init_thread(&argc, &argv, MPI_THREAD_MULTIPLE, &provided);
    g_active = true;
    g_multiple = provided >= MPI_THREAD_MULTIPLE;
    MPI_Comm_rank(MPI_COMM_WORLD, &g_rank);
    MPI_Comm_size(MPI_COMM_WORLD, &g_size);
#else
    for (const char* v : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE"})
        if (const char* s = std::getenv(v); s && std::atoi(s) > 1)
            throw InputError(std::string("started by an MPI launcher (") + v + "=" + s +
                             ") but built without MPI (GRANREPRO_MPI=OFF); use --threads, or --points I/N shards");
#endif
}

void finalize() {
#ifdef GRANREPRO_HAVE_MPI
    if (g_active) MPI_Finalize();
    g_active = false;
#endif
}

int rank() { return g_rank; }
int size() { return g_size; }
bool threads_may_call_mpi() { return g_multiple; }

void abort(int code) {
#ifdef GRANREPRO_HAVE_MPI
    if (g_active) MPI_Abort(MPI_COMM_WORLD, code);
#endif
    std::_Exit(code);
}

} // namespace granrepro::mpi
