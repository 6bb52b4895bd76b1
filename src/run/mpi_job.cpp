#include "run/mpi_job.h"

#include <algorithm>
#include <cstdlib>
#include <string>

#if LENSRT_WITH_MPI
#include <mpi.h>
#endif

namespace lensrt {
namespace {

// A launcher's variable as a count or rank; -1 when absent or not a number.
int number(const std::function<const char*(const char*)>& getenv, const char* name) {
  const char* text = getenv(name);
  if (!text || !*text) return -1;
  char* end = nullptr;
  const long value = std::strtol(text, &end, 10);
  return *end == '\0' && value >= 0 && value <= 1 << 30 ? int(value) : -1;
}

}  // namespace

bool MpiJob::builtWithMpi() {
  return LENSRT_WITH_MPI != 0;
}

std::string MpiJob::refusal(const std::optional<Launch>& l, bool withMpi) {
  if (withMpi || !l || (l->size <= 1 && l->rank == 0)) return {};
  return (l->size > 1 ? "started as one of " + std::to_string(l->size) + " processes"
                      : "started as process " + std::to_string(l->rank)) +
         " of an MPI job, but this lensrt was built without MPI: every process would render the whole "
         "image alone (install libopenmpi-dev and build again, or run lensrt without mpirun)";
}

std::optional<MpiJob::Launch> MpiJob::launch(const std::function<const char*(const char*)>& getenv) {
  struct Launcher {
    const char* size;
    const char* rank;
    bool sizeAlone;  // whether the size variable alone means a launch
  };
  // Open MPI's mpirun; MPICH's hydra (PMI); PMIx launchers such as srun, whose
  // size Slurm gives (SLURM_NTASKS is also set in a batch job's own shell).
  constexpr Launcher kLaunchers[] = {{"OMPI_COMM_WORLD_SIZE", "OMPI_COMM_WORLD_RANK", true},
                                     {"PMI_SIZE", "PMI_RANK", true},
                                     {"SLURM_NTASKS", "PMIX_RANK", false}};
  for (const Launcher& l : kLaunchers) {
    const int size = number(getenv, l.size), rank = number(getenv, l.rank);
    if (rank < 0 && (size < 0 || !l.sizeAlone)) continue;
    return Launch{std::max(size, 0), std::max(rank, 0)};
  }
  return std::nullopt;
}

#if LENSRT_WITH_MPI

MpiJob::MpiJob(int& argc, char**& argv) {
  if (!launch(std::getenv)) return;
  // Only the main thread calls MPI (the render threads never do).
  int provided = 0;
  MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided);
  initialized_ = true;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
}

MpiJob::~MpiJob() {
  if (initialized_) MPI_Finalize();
}

std::optional<MpiJob::Failure> MpiJob::agree(const std::optional<Failure>& mine) {
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

std::string MpiJob::shareFromMain(const std::string& text) const {
  if (size_ == 1) return text;
  int length = int(text.size());
  MPI_Bcast(&length, 1, MPI_INT, 0, MPI_COMM_WORLD);
  std::string shared = isMain() ? text : std::string(std::size_t(length), '\0');
  MPI_Bcast(shared.data(), length, MPI_CHAR, 0, MPI_COMM_WORLD);
  return shared;
}

void MpiJob::abort(int status) const {
  if (initialized_) MPI_Abort(MPI_COMM_WORLD, status);
  std::exit(status);
}

#else

MpiJob::MpiJob(int&, char**&) {
  const std::optional<Launch> l = launch(std::getenv);
  unsupportedLaunch_ = refusal(l, false);
  if (!unsupportedLaunch_.empty()) rank_ = l->rank;  // rank 0 alone says it
}
MpiJob::~MpiJob() = default;

std::optional<MpiJob::Failure> MpiJob::agree(const std::optional<Failure>& mine) {
  agreed_ = true;
  return mine;
}

std::string MpiJob::shareFromMain(const std::string& text) const {
  return text;
}

void MpiJob::abort(int status) const {
  std::exit(status);
}

#endif

}  // namespace lensrt
