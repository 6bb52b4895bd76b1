// The MPI job this process belongs to (`mpirun -np N lensrt ...`, `srun`),
// or a job of one. MPI is joined only when an MPI launcher started the
// process, so a plain `lensrt` never pays for it; a build without MPI is
// always a job of one.
#pragma once

#include <functional>
#include <optional>
#include <string>

namespace lensrt {

class MpiJob {
 public:
  MpiJob(int& argc, char**& argv);
  // A job of one process, whatever started this one: a rank's own part of a
  // job whose ranks work apart (whole frames of --frames).
  MpiJob() = default;
  ~MpiJob();
  MpiJob(const MpiJob&) = delete;
  MpiJob& operator=(const MpiJob&) = delete;

  static bool builtWithMpi();

  // What an MPI launcher told this process through its environment (Open
  // MPI's mpirun, MPICH's hydra, PMIx and Slurm's srun): the job's size (0
  // when the launcher does not say) and this process's rank. Empty when no
  // launcher started it.
  struct Launch {
    int size = 0;
    int rank = 0;
  };
  static std::optional<Launch> launch(const std::function<const char*(const char*)>& getenv);

  // The error of a process that cannot take part in the job it was started
  // in, empty when it can: a build without MPI, started as one of several
  // processes, would render the whole image in each of them, all writing the
  // same output.
  static std::string refusal(const std::optional<Launch>& launch, bool withMpi);
  // refusal() for this process.
  const std::string& unsupportedLaunch() const { return unsupportedLaunch_; }
  int rank() const { return rank_; }
  int size() const { return size_; }
  bool isMain() const { return rank_ == 0; }

  // A rank's error: its one line (without "lensrt: error: ") and exit status.
  struct Failure {
    int rank = 0;
    int status = 1;
    std::string line;
  };
  // Collective, called once by every rank when its set-up is done (or has
  // failed): returns the failure of the lowest failing rank, the same on
  // every rank, so that a scene error is reported once and no rank waits
  // for one that has given up.
  std::optional<Failure> agree(const std::optional<Failure>& mine);
  bool agreed() const { return agreed_; }
  // Collective: rank 0's `text` on every rank (the others' is ignored).
  std::string shareFromMain(const std::string& text) const;
  // Ends every rank of the job with `status` (an error after set-up).
  [[noreturn]] void abort(int status) const;

 private:
  int rank_ = 0, size_ = 1;
  bool initialized_ = false, agreed_ = false;
  std::string unsupportedLaunch_;
};

}  // namespace lensrt
