// The MPI pool (see mpi_pool.hpp). Messages: a worker sends its last row as JSON (empty the first time)
// with tag kResult; rank 0 answers with the next run's index, or -1 when none is left (tag kWork).
#include "mpi_pool.hpp"

#include <cstdlib>
#include <limits>

#include "stop_signal.hpp"
#include "local_pool.hpp"

#ifdef EDE_HAVE_MPI
#include <mpi.h>
#endif

namespace ede::sweep {

bool launched_by_mpirun() {
  return std::getenv("OMPI_COMM_WORLD_SIZE") || std::getenv("PMI_SIZE") || std::getenv("PMIX_RANK");
}

#ifdef EDE_HAVE_MPI

namespace {

constexpr int kResult = 1, kWork = 2;

void send_index(long long k, int to) { MPI_Send(&k, 1, MPI_LONG_LONG, to, kWork, MPI_COMM_WORLD); }

std::vector<RunRow> hand_out(const Sweep& s, int size) {
  std::vector<RunRow> rows;
  for (std::size_t k = 0; k < s.runs.size(); ++k) rows.push_back(pending_row(s, k));  // until its row comes back
  if (s.on_rows) s.on_rows(rows);
  std::size_t next = 0, done = 0;
  int working = size - 1;
  while (working > 0) {
    MPI_Status st;
    MPI_Probe(MPI_ANY_SOURCE, kResult, MPI_COMM_WORLD, &st);
    int length = 0;
    MPI_Get_count(&st, MPI_CHAR, &length);
    std::string text(std::size_t(length), '\0');
    MPI_Recv(text.data(), length, MPI_CHAR, st.MPI_SOURCE, kResult, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    if (!text.empty()) {
      auto row = row_from_json(text, "the row from rank " + std::to_string(st.MPI_SOURCE));
      if (row && row.value().index < rows.size()) {
        rows[row.value().index] = row.value();
        report_run(s, rows[row.value().index], ++done);
        if (s.on_rows) s.on_rows(rows);
      }
    }
    if (next < s.runs.size() && !stop_requested()) {
      send_index((long long)next++, st.MPI_SOURCE);
    } else {
      send_index(-1, st.MPI_SOURCE);
      --working;
    }
  }
  for (std::size_t k = 0; k < next; ++k)  // handed out, and its worker came back without a readable row
    if (rows[k].status == "pending") {
      rows[k].status = "lost";
      rows[k].error = "no readable row came back from the worker that ran it: run the sweep again";
    }
  for (std::size_t k = next; k < s.runs.size(); ++k) {  // not handed out (interrupted)
    rows[k].status = "interrupted";
    rows[k].error = "not run: the sweep was interrupted";
  }
  return rows;
}

}  // namespace

Result<int> mpi_start(int& argc, char**& argv) {
  MPI_Init(&argc, &argv);
  int size = 1;
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  return size;
}

int mpi_rank() {
  int rank = 0, started = 0;
  MPI_Initialized(&started);
  if (!started) return 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  return rank;
}

void mpi_finish() { MPI_Finalize(); }

void mpi_abort(int code) { MPI_Abort(MPI_COMM_WORLD, code); }

std::optional<std::vector<RunRow>> run_mpi(const Sweep& s) {
  int size = 1;
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  if (mpi_rank() == 0) return hand_out(s, size);
  std::string last;
  for (;;) {
    MPI_Send(last.data(), int(last.size()), MPI_CHAR, 0, kResult, MPI_COMM_WORLD);
    long long k = -1;
    MPI_Recv(&k, 1, MPI_LONG_LONG, 0, kWork, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    if (k < 0 || std::size_t(k) >= s.runs.size()) return std::nullopt;
    last = row_to_json(execute_run(s, std::size_t(k)));
  }
}

#else

Result<int> mpi_start(int&, char**&) {
  return Error{"this ede-sweep was built without MPI (CMake found no MPI): install libopenmpi-dev and rebuild, or "
               "run without mpirun (all local cores: -j N)"};
}
int mpi_rank() { return 0; }
void mpi_finish() {}
void mpi_abort(int) {}
std::optional<std::vector<RunRow>> run_mpi(const Sweep&) { return std::nullopt; }

#endif

}  // namespace ede::sweep
