#include "app/cluster.h"

#include <cstdlib>
#include <string>

#if LENSRT_WITH_MPI
#include <mpi.h>
#endif

namespace lensrt {
namespace {

// Set by Open MPI's mpirun, by PMI/PMIx launchers (srun, MPICH's hydra).
bool startedByMpiLauncher() {
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_SIZE", "PMI_RANK"})
    if (std::getenv(name)) return true;
  return false;
}

}  // namespace

bool Cluster::builtWithMpi() {
  return LENSRT_WITH_MPI != 0;
}

#if LENSRT_WITH_MPI

Cluster::Cluster(int& argc, char**& argv) {
  if (!startedByMpiLauncher()) return;
  // Only the main thread calls MPI (the render threads never do).
  int provided = 0;
  MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided);
  initialized_ = true;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
}

Cluster::~Cluster() {
  if (initialized_) MPI_Finalize();
}

std::optional<Cluster::Failure> Cluster::agree(const std::optional<Failure>& mine) {
  agreed_ = true;
  if (size_ == 1) return mine;
  const int candidate = mine ? rank_ : size_;
  int first = size_;
  MPI_Allreduce(&candidate, &first, 1, MPI_INT, MPI_MIN, MPI_COMM_WORLD);
  if (first == size_) return std::nullopt;
  Failure failure;
  failure.rank = first;
  int header[2] = {mine ? mine->status : 0, mine ? int(mine->line.size()) : 0};
  MPI_Bcast(header, 2, MPI_INT, first, MPI_COMM_WORLD);
  std::string text = mine ? mine->line : std::string();
  text.resize(std::size_t(header[1]));
  MPI_Bcast(text.data(), header[1], MPI_CHAR, first, MPI_COMM_WORLD);
  failure.status = header[0];
  failure.line = text;
  return failure;
}

std::string Cluster::shareFromMain(const std::string& text) const {
  if (size_ == 1) return text;
  int length = int(text.size());
  MPI_Bcast(&length, 1, MPI_INT, 0, MPI_COMM_WORLD);
  std::string shared = isMain() ? text : std::string(std::size_t(length), '\0');
  MPI_Bcast(shared.data(), length, MPI_CHAR, 0, MPI_COMM_WORLD);
  return shared;
}

void Cluster::abort(int status) const {
  if (initialized_) MPI_Abort(MPI_COMM_WORLD, status);
  std::exit(status);
}

#else

Cluster::Cluster(int&, char**&) {}
Cluster::~Cluster() = default;

std::optional<Cluster::Failure> Cluster::agree(const std::optional<Failure>& mine) {
  agreed_ = true;
  return mine;
}

std::string Cluster::shareFromMain(const std::string& text) const {
  return text;
}

void Cluster::abort(int status) const {
  std::exit(status);
}

#endif

}  // namespace lensrt
