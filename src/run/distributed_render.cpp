#include "run/distributed_render.h"

#include <fmt/core.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <thread>
#include <vector>

#include "render/render_identity.h"

#if LENSRT_WITH_MPI
#include <mpi.h>
#endif

namespace lensrt {

namespace {

// The identity's values, NUL-separated (no value holds a NUL).
std::string packIdentity(const ImageMetadata& identity) {
  std::string text;
  for (const char* key : kRenderIdentityKeys) {
    const auto it = identity.find(key);
    text += (it == identity.end() ? std::string() : it->second) + '\0';
  }
  return text;
}

ImageMetadata unpackIdentity(const std::string& text) {
  ImageMetadata identity;
  std::size_t at = 0;
  for (const char* key : kRenderIdentityKeys) {
    const std::size_t end = std::min(text.find('\0', at), text.size());
    identity[key] = text.substr(at, end - at);
    at = std::min(end + 1, text.size());
  }
  return identity;
}

}  // namespace

std::optional<MpiJob::Failure> setUpTogether(MpiJob& mpi, const std::string& scene,
                                             const ImageMetadata& identity) {
  if (auto failure = mpi.agree(std::nullopt)) return failure;
  const ImageMetadata main = unpackIdentity(mpi.shareFromMain(packIdentity(identity)));
  std::optional<MpiJob::Failure> mine;
  if (const std::string diff = renderIdentityDifference(identity, main); !diff.empty())
    mine = MpiJob::Failure{mpi.rank(), 1,
                           fmt::format("{}: this rank's render differs from rank 0's: {}", scene, diff)};
  return mpi.agree(mine);
}

#if LENSRT_WITH_MPI
namespace {

// Messages: a rank asks for work with the strip it has just rendered (none
// the first time); rank 0 answers with a strip or with the end of the job.
constexpr int kTagRequest = 1, kTagStrip = 2, kTagEnd = 3;
// Waiting ranks poll instead of blocking: Open MPI's blocking calls spin,
// which would take a core from the render threads.
constexpr auto kPoll = std::chrono::microseconds(200);
// Passes across ranks grow to at least about this long (one process: the
// control's 1 s): every pass moves the running sums of each strip to a rank
// and back and ends with ranks waiting for the last strips, which at 1 s
// passes cost a 640x360 full-lens render 1.7 GB of messages and 10% of rank
// 0's time. A stop request is still honoured at the end of the pass in flight.
constexpr double kMinPassSeconds = 4.0;

void waitFor(int source, int tag, MPI_Status& status) {
  int flag = 0;
  while (MPI_Iprobe(source, tag, MPI_COMM_WORLD, &flag, &status), !flag) std::this_thread::sleep_for(kPoll);
}

std::vector<std::byte> receiveBytes(const MPI_Status& probed) {
  int count = 0;
  MPI_Get_count(&probed, MPI_BYTE, &count);
  std::vector<std::byte> bytes(static_cast<std::size_t>(count));
  MPI_Recv(bytes.data(), count, MPI_BYTE, probed.MPI_SOURCE, probed.MPI_TAG, MPI_COMM_WORLD,
           MPI_STATUS_IGNORE);
  return bytes;
}

// The strips of a region: rows of about `rows` pixels.
std::vector<PixelRegion> stripsOf(const PixelRegion& region, int rows) {
  std::vector<PixelRegion> strips;
  for (int y = region.y0; y < region.y1; y += rows)
    strips.push_back({region.x0, region.x1, y, std::min(y + rows, region.y1)});
  return strips;
}

FilmState extract(FilmState& state, const PixelRegion& strip) {
  FilmState part(strip, state.aovs());
  for (int y = strip.y0; y < strip.y1; ++y)
    for (int x = strip.x0; x < strip.x1; ++x) {
      part.pixel(x, y) = state.pixel(x, y);
      if (state.aovs().coords()) part.coords(x, y) = state.coords(x, y);
    }
  part.setSamplesDone(state.samplesDone());
  return part;
}

// Copies a rendered strip back; returns the blocked camera rays it added.
std::uint64_t insert(FilmState& state, FilmState& part) {
  const PixelRegion& strip = part.region();
  if (!state.region().contains(strip)) throw std::runtime_error("a rank sent back a strip outside the image");
  for (int y = strip.y0; y < strip.y1; ++y)
    for (int x = strip.x0; x < strip.x1; ++x) {
      state.pixel(x, y) = part.pixel(x, y);
      if (state.aovs().coords()) state.coords(x, y) = part.coords(x, y);
    }
  return part.blockedCameraRays;
}

void renderPart(const Camera& camera, const Integrator& integrator, const RenderSettings& settings,
                FilmState& part, int target, Progress* progress) {
  RenderSettings s = settings;
  s.samplesPerPixel = target;
  s.region = part.region();
  renderPasses(camera, integrator, s, part, nullptr, progress);
}

}  // namespace

bool renderAcrossRanks(const MpiJob& mpi, const Camera& camera, const Integrator& integrator,
                       const RenderSettings& settings, FilmState& state, const PassControl& control,
                       Progress* progress, int& signal, GatherCost* cost) {
  GatherCost spent;
  using Clock = std::chrono::steady_clock;
  const std::vector<PixelRegion> strips = stripsOf(state.region(), std::max(1, settings.tileSize));
  const int target = settings.samplesPerPixel;
  std::vector<int> waiting;  // ranks whose request for work is not answered yet
  signal = 0;
  // Answers one request: takes its strip back, then hands out `next` if any.
  const auto serve = [&](std::atomic<int>& next, int passTarget, int& outstanding) {
    MPI_Status status;
    int flag = 0;
    MPI_Iprobe(MPI_ANY_SOURCE, kTagRequest, MPI_COMM_WORLD, &flag, &status);
    if (!flag) return false;
    const auto start = Clock::now();
    const std::vector<std::byte> bytes = receiveBytes(status);
    spent.bytes += bytes.size();
    if (bytes.empty()) throw std::runtime_error("an empty request from a rank");
    if (bytes[0] != std::byte{0} && signal == 0) signal = int(bytes[0]);
    if (bytes.size() > 1) {
      FilmState part = FilmState::fromBytes(std::span(bytes).subspan(1));
      state.blockedCameraRays += insert(state, part);
      if (progress)
        progress->add(part.region().pixelCount() * std::uint64_t(passTarget - state.samplesDone()));
      --outstanding;
    }
    waiting.push_back(status.MPI_SOURCE);
    spent.seconds += std::chrono::duration<double>(Clock::now() - start).count();
    return true;
  };
  const auto handOut = [&](std::atomic<int>& next, int passTarget, int& outstanding) {
    while (!waiting.empty()) {
      const int i = next.fetch_add(1);
      if (i >= int(strips.size())) return;
      const auto start = Clock::now();
      std::vector<std::byte> message(4);
      std::memcpy(message.data(), &passTarget, 4);
      const std::vector<std::byte> part = extract(state, strips[std::size_t(i)]).toBytes();
      message.insert(message.end(), part.begin(), part.end());
      MPI_Send(message.data(), int(message.size()), MPI_BYTE, waiting.back(), kTagStrip, MPI_COMM_WORLD);
      waiting.pop_back();
      ++outstanding;
      spent.bytes += message.size();
      spent.seconds += std::chrono::duration<double>(Clock::now() - start).count();
    }
  };

  bool finished = true;
  int passSpp = 1;
  while (state.samplesDone() < target) {
    const int first = state.samplesDone(), last = std::min(target, first + passSpp);
    const auto start = std::chrono::steady_clock::now();
    std::atomic<int> next{0};
    std::atomic<bool> localDone{false};
    std::uint64_t localBlocked = 0;
    // Rank 0's own share, in a thread, so that this one keeps serving.
    std::thread local([&] {
      for (int i; (i = next.fetch_add(1)) < int(strips.size());) {
        FilmState part = extract(state, strips[std::size_t(i)]);
        renderPart(camera, integrator, settings, part, last, progress);
        localBlocked += insert(state, part);
      }
      localDone = true;
    });
    int outstanding = 0;
    try {
      handOut(next, last, outstanding);
      while (!localDone || outstanding > 0) {
        if (serve(next, last, outstanding))
          handOut(next, last, outstanding);
        else
          std::this_thread::sleep_for(kPoll);
      }
    } catch (...) {
      local.join();
      throw;
    }
    local.join();
    state.blockedCameraRays += localBlocked;
    state.setSamplesDone(last);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (seconds * 2 < std::max(control.passSeconds, kMinPassSeconds) && passSpp < (1 << 20)) passSpp *= 2;
    if (state.samplesDone() >= target) break;
    if ((control.stopRequested && control.stopRequested()) || signal != 0) {
      finished = false;
      break;
    }
    if (control.afterPass) control.afterPass(state);
  }
  // Every other rank ends up waiting for work: tell each the job is over.
  int outstanding = 0;
  std::atomic<int> none{int(strips.size())};
  while (int(waiting.size()) < mpi.size() - 1)
    if (!serve(none, target, outstanding)) std::this_thread::sleep_for(kPoll);
  for (const int rank : waiting) MPI_Send(nullptr, 0, MPI_BYTE, rank, kTagEnd, MPI_COMM_WORLD);
  if (cost) *cost = spent;
  return finished;
}

void workForMain(const MpiJob&, const Camera& camera, const Integrator& integrator,
                 const RenderSettings& settings, const std::function<int()>& signal) {
  std::vector<std::byte> done;
  while (true) {
    std::vector<std::byte> request{std::byte(std::uint8_t(signal()))};
    request.insert(request.end(), done.begin(), done.end());
    MPI_Send(request.data(), int(request.size()), MPI_BYTE, 0, kTagRequest, MPI_COMM_WORLD);
    MPI_Status status;
    waitFor(0, MPI_ANY_TAG, status);
    const std::vector<std::byte> bytes = receiveBytes(status);
    if (status.MPI_TAG == kTagEnd) return;
    if (bytes.size() < 4) throw std::runtime_error("a malformed strip from rank 0");
    int target = 0;
    std::memcpy(&target, bytes.data(), 4);
    FilmState part = FilmState::fromBytes(std::span(bytes).subspan(4));
    part.blockedCameraRays = 0;
    renderPart(camera, integrator, settings, part, target, nullptr);
    done = part.toBytes();
  }
}

#else

bool renderAcrossRanks(const MpiJob&, const Camera&, const Integrator&, const RenderSettings&, FilmState&,
                       const PassControl&, Progress*, int&, GatherCost*) {
  throw std::logic_error("lensrt was built without MPI");
}

void workForMain(const MpiJob&, const Camera&, const Integrator&, const RenderSettings&,
                 const std::function<int()>&) {
  throw std::logic_error("lensrt was built without MPI");
}

#endif

}  // namespace lensrt
