// The MPI world this process belongs to: one rank of one when granrepro was built without MPI
// (GRANREPRO_MPI=OFF) or started without mpirun. Only the sweep (distributed_sweep.cpp) and
// main() talk to MPI; experiments and engines never do.
#pragma once

namespace granrepro::mpi {

// MPI_Init_thread (asking for MPI_THREAD_MULTIPLE, so that every --threads worker of a rank can
// fetch its own points). Without MPI: refuses (InputError) to run under an MPI launcher, where
// every rank would compute and write everything.
void init(int& argc, char**& argv);
void finalize();
int rank();
int size();
bool threads_may_call_mpi(); // MPI_THREAD_MULTIPLE was granted
// Ends every rank (MPI_Abort), or this process without MPI.
[[noreturn]] void abort(int code);

} // namespace granrepro::mpi
