// How lensrt reads the MPI launcher's environment: which processes belong to
// a job, and the error of a build without MPI started as several processes.
#include "run/mpi_job.h"

#include <gtest/gtest.h>

#include <map>
#include <string>

namespace lensrt {
namespace {

std::optional<MpiJob::Launch> launchWith(const std::map<std::string, std::string>& env) {
  return MpiJob::launch([&](const char* name) -> const char* {
    const auto it = env.find(name);
    return it == env.end() ? nullptr : it->second.c_str();
  });
}

TEST(MpiJob, ReadsEachLaunchersSizeAndRank) {
  EXPECT_FALSE(launchWith({}));
  // A Slurm allocation without srun's PMIx is not a launch.
  EXPECT_FALSE(launchWith({{"SLURM_NTASKS", "4"}}));
  const auto ompi = launchWith({{"OMPI_COMM_WORLD_SIZE", "3"}, {"OMPI_COMM_WORLD_RANK", "2"}});
  ASSERT_TRUE(ompi);
  EXPECT_EQ(ompi->size, 3);
  EXPECT_EQ(ompi->rank, 2);
  const auto hydra = launchWith({{"PMI_SIZE", "2"}, {"PMI_RANK", "0"}});
  ASSERT_TRUE(hydra);
  EXPECT_EQ(hydra->size, 2);
  EXPECT_EQ(hydra->rank, 0);
  const auto srun = launchWith({{"PMIX_RANK", "1"}, {"SLURM_NTASKS", "8"}});
  ASSERT_TRUE(srun);
  EXPECT_EQ(srun->size, 8);
  EXPECT_EQ(srun->rank, 1);
  // A PMIx launch that does not say its size.
  const auto unknown = launchWith({{"PMIX_RANK", "0"}});
  ASSERT_TRUE(unknown);
  EXPECT_EQ(unknown->size, 0);
  // Values that are not counts are ignored.
  EXPECT_FALSE(launchWith({{"OMPI_COMM_WORLD_SIZE", "two"}}));
  EXPECT_FALSE(launchWith({{"PMI_RANK", "-1"}}));
}

TEST(MpiJob, ABuildWithoutMpiRefusesAJobOfSeveralProcesses) {
  const auto refusal = [](int size, int rank, bool withMpi) {
    return MpiJob::refusal(MpiJob::Launch{size, rank}, withMpi);
  };
  EXPECT_NE(refusal(2, 1, false)
                .find("started as one of 2 processes of an MPI job, but this lensrt was built "
                      "without MPI"),
            std::string::npos)
      << refusal(2, 1, false);
  EXPECT_NE(refusal(0, 3, false).find("started as process 3 of an MPI job"), std::string::npos);
  // A job of one, no launcher, or a build with MPI: nothing to refuse.
  EXPECT_EQ(refusal(1, 0, false), "");
  EXPECT_EQ(refusal(0, 0, false), "");
  EXPECT_EQ(MpiJob::refusal(std::nullopt, false), "");
  EXPECT_EQ(refusal(4, 2, true), "");
}

}  // namespace
}  // namespace lensrt
