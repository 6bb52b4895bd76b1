#include "render/film_state.h"

#include <array>
#include <cstring>
#include <stdexcept>
#include <string>

namespace lensrt {
namespace {

// Version 3 keeps each pixel's planar depth (Z); version 2 added the
// coverage counts (alpha). Older sums cannot give them.
constexpr std::array<char, 8> kMagic{'L', 'R', 'T', 'S', 'U', 'M', 'S', '3'};
constexpr std::array<char, 8> kMagicVersion1{'L', 'R', 'T', 'S', 'U', 'M', 'S', '1'};
constexpr std::array<char, 8> kMagicVersion2{'L', 'R', 'T', 'S', 'U', 'M', 'S', '2'};
// magic, x0 x1 y0 y1, samples done, AOV bits (int32 each), blocked rays (uint64);
// then every pixel's sums, then (with a coordinate AOV) every pixel's
// coordinate sums (bits 64-256, which older files never set).
constexpr std::size_t kHeaderBytes = kMagic.size() + 6 * 4 + 8;

std::int32_t aovBits(const AovSelection& a) {
  return (a.depth ? 1 : 0) | (a.normal ? 2 : 0) | (a.albedo ? 4 : 0) | (a.variance ? 8 : 0) |
         (a.spp ? 16 : 0) | (a.z ? 32 : 0) | (a.position ? 64 : 0) | (a.uv ? 128 : 0) |
         (a.objectCoords ? 256 : 0);
}

}  // namespace

FilmState::FilmState(const PixelRegion& region, const AovSelection& aovs)
    : region_(region), aovs_(aovs), pixels_(region.empty() ? 0 : region.pixelCount()) {
  if (region.empty()) throw std::invalid_argument("the region to render is empty");
  if (aovs.ids()) ids_.resize(pixels_.size());
  if (aovs.flow) flow_.resize(pixels_.size());
  if (aovs.coords()) coords_.resize(pixels_.size());
}

std::uint64_t FilmState::droppedSamples() const {
  std::uint64_t n = 0;
  for (const PixelAccumulator& p : pixels_) n += p.droppedSamples();
  return n;
}

std::uint64_t FilmState::samplesTaken() const {
  std::uint64_t n = 0;
  for (const PixelAccumulator& p : pixels_) n += p.samplesTaken();
  return n;
}

Image FilmState::image(int frameWidth, int frameHeight) const {
  Image out(region_.width(), region_.height(), filmChannels(aovs_));
  out.originX = region_.x0;
  out.originY = region_.y0;
  if (!(region_ == PixelRegion::wholeFrame(frameWidth, frameHeight))) {
    out.frameWidth = frameWidth;
    out.frameHeight = frameHeight;
  }
  const std::size_t channels = out.channelCount();
  for (std::size_t i = 0; i < pixels_.size(); ++i) pixels_[i].write(aovs_, &out.pixels[i * channels]);
  // The ID channels, then the coordinate channels, then flow's, last (filmChannels).
  const std::size_t flowChannels = aovs_.flow ? 4 : 0;
  const std::size_t coordinates =
      (aovs_.position ? 3 : 0) + (aovs_.uv ? 2 : 0) + (aovs_.objectCoords ? 3 : 0);
  if (aovs_.coords())
    for (std::size_t i = 0; i < pixels_.size(); ++i)
      coords_[i].write(aovs_, &out.pixels[i * channels + channels - flowChannels - coordinates]);
  if (aovs_.ids()) {
    const std::size_t first = channels - flowChannels - coordinates - (aovs_.cryptoObject ? 4 * 3 : 0) -
                              (aovs_.cryptoMaterial ? 4 * 3 : 0) - (aovs_.objectId ? 1 : 0);
    for (std::size_t i = 0; i < pixels_.size(); ++i) {
      float* p = &out.pixels[i * channels + first];
      if (aovs_.cryptoObject) {
        ids_[i].writeRanks(false, p);
        p += 2 * kCryptoRanks;
      }
      if (aovs_.cryptoMaterial) {
        ids_[i].writeRanks(true, p);
        p += 2 * kCryptoRanks;
      }
      if (aovs_.objectId) *p = float(ids_[i].topNode());
    }
  }
  if (aovs_.flow)
    for (std::size_t i = 0; i < pixels_.size(); ++i) flow_[i].write(&out.pixels[(i + 1) * channels - 4]);
  return out;
}

std::vector<std::byte> FilmState::toBytes() const {
  if (const std::string unsaved = aovs_.unsavedAovs(); !unsaved.empty())
    throw std::invalid_argument(
        "the AOVs " + unsaved +
        " cannot be saved as running sums yet: render them without ranks or a checkpoint");
  std::vector<std::byte> bytes(kHeaderBytes + pixels_.size() * PixelAccumulator::kStateBytes +
                               coords_.size() * CoordinateSums::kStateBytes);
  std::byte* p = bytes.data();
  std::memcpy(p, kMagic.data(), kMagic.size());
  p += kMagic.size();
  for (std::int32_t v : {std::int32_t(region_.x0), std::int32_t(region_.x1), std::int32_t(region_.y0),
                         std::int32_t(region_.y1), std::int32_t(samplesDone_), aovBits(aovs_)}) {
    std::memcpy(p, &v, 4);
    p += 4;
  }
  std::memcpy(p, &blockedCameraRays, 8);
  p += 8;
  for (const PixelAccumulator& px : pixels_) {
    px.saveState(p);
    p += PixelAccumulator::kStateBytes;
  }
  for (const CoordinateSums& c : coords_) {
    c.saveState(p);
    p += CoordinateSums::kStateBytes;
  }
  return bytes;
}

FilmState FilmState::fromBytes(std::span<const std::byte> bytes) {
  for (const auto& older : {kMagicVersion1, kMagicVersion2})
    if (bytes.size() >= kMagic.size() && std::memcmp(bytes.data(), older.data(), kMagic.size()) == 0)
      throw std::invalid_argument(
          "running sums of an older lensrt, without the sums this one keeps: render it again");
  if (bytes.size() < kHeaderBytes || std::memcmp(bytes.data(), kMagic.data(), kMagic.size()) != 0)
    throw std::invalid_argument("not a lensrt running-sums file");
  const std::byte* p = bytes.data() + kMagic.size();
  std::int32_t v[6];
  for (std::int32_t& x : v) {
    std::memcpy(&x, p, 4);
    p += 4;
  }
  std::uint64_t blocked = 0;
  std::memcpy(&blocked, p, 8);
  p += 8;
  const PixelRegion region{v[0], v[1], v[2], v[3]};
  if (region.empty() || region.x0 < 0 || region.y0 < 0 || v[4] < 0 || v[5] < 0 || v[5] > 511)
    throw std::invalid_argument("the running-sums file's header is corrupt");
  AovSelection aovs;
  aovs.depth = v[5] & 1;
  aovs.normal = v[5] & 2;
  aovs.albedo = v[5] & 4;
  aovs.variance = v[5] & 8;
  aovs.spp = v[5] & 16;
  aovs.z = v[5] & 32;
  aovs.position = v[5] & 64;
  aovs.uv = v[5] & 128;
  aovs.objectCoords = v[5] & 256;
  const std::uint64_t expected =
      kHeaderBytes + region.pixelCount() *
                         (PixelAccumulator::kStateBytes + (aovs.coords() ? CoordinateSums::kStateBytes : 0));
  if (bytes.size() != expected)
    throw std::invalid_argument("the running-sums file has " + std::to_string(bytes.size()) +
                                " bytes, its header says " + std::to_string(expected));
  FilmState state(region, aovs);
  state.samplesDone_ = v[4];
  state.blockedCameraRays = blocked;
  for (PixelAccumulator& px : state.pixels_) {
    px.loadState(p);
    p += PixelAccumulator::kStateBytes;
  }
  for (CoordinateSums& c : state.coords_) {
    c.loadState(p);
    p += CoordinateSums::kStateBytes;
  }
  return state;
}

}  // namespace lensrt
