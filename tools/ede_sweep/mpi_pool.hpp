// Running a sweep on MPI ranks (built only when CMake finds MPI: EDE_HAVE_MPI): rank 0 hands out runs
// one at a time to whichever worker asks next (dynamic: a slow run does not hold up the others), workers
// do each run with execute_run (a child process on their own node, logs under their results folder) and
// send the row back as text; rank 0 alone writes the tables, so no shared file system is needed.
// A rank that dies ends the whole job (OpenMPI aborts every rank when one dies: MPI offers no portable
// recovery); the rows already written and the logs stay, the tables rank 0 keeps current (Sweep::on_rows)
// say which runs were still pending, and running the sweep again reuses the finished runs and resumes the
// killed ones (docs/sweeps.md). Rejected: static blocks of runs per rank (runs of a
// sweep differ in length by orders of magnitude) and MPI-IO for the tables (the table is small).
#pragma once

#include <optional>
#include <vector>

#include "sweep.hpp"

namespace ede::sweep {

// Whether this process was started by mpirun (OpenMPI's or a PMI launcher's variables are set).
bool launched_by_mpirun();

// Starts MPI; the world size (1: run locally as usual). Fails without MPI support in this build.
Result<int> mpi_start(int& argc, char**& argv);
int mpi_rank();
void mpi_finish();
// Ends every rank of the job (rank 0 refusing the sweep while the workers wait for work).
void mpi_abort(int code);

// Rank 0: hands out the runs and returns every row. Other ranks: work until told to stop, return nothing.
std::optional<std::vector<RunRow>> run_mpi(const Sweep& s);

}  // namespace ede::sweep
