#include "image/exr_io.h"

#include <Iex.h>
#include <Imath/half.h>
#include <ImfChannelList.h>
#include <ImfChromaticitiesAttribute.h>
#include <ImfCompressionAttribute.h>
#include <ImfDoubleAttribute.h>
#include <ImfFloatAttribute.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfIO.h>
#include <ImfInputFile.h>
#include <ImfIntAttribute.h>
#include <ImfMatrixAttribute.h>
#include <ImfOutputFile.h>
#include <ImfStandardAttributes.h>
#include <ImfStdIO.h>
#include <ImfStringAttribute.h>
#include <ImfVecAttribute.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <map>
#include <memory>
#include <set>
#include <sstream>
#include <vector>

#include "core/error.h"
#include "image/capture_date.h"

namespace lensrt {
namespace {

// OpenEXR's messages can span lines; InputError promises one.
std::string oneLine(std::string s) {
  std::replace(s.begin(), s.end(), '\n', ' ');
  while (!s.empty() && s.back() == ' ') s.pop_back();
  return s.empty() ? "unknown OpenEXR error" : s;
}

// The encoded file collects here; the caller writes it out and checks that
// write, which OpenEXR's own file stream would report only in part (the
// offset table is written from a destructor that swallows errors).
class MemoryOStream : public Imf::OStream {
 public:
  explicit MemoryOStream(const std::string& name) : Imf::OStream(name.c_str()) {}
  void write(const char c[], int n) override {
    if (position_ + std::size_t(n) > bytes_.size()) bytes_.resize(position_ + std::size_t(n));
    std::memcpy(bytes_.data() + position_, c, std::size_t(n));
    position_ += std::size_t(n);
  }
  uint64_t tellp() override { return position_; }
  void seekp(uint64_t pos) override { position_ = std::size_t(pos); }
  std::string take() { return std::move(bytes_); }

 private:
  std::string bytes_;
  std::size_t position_ = 0;
};

class MemoryIStream : public Imf::IStream {
 public:
  MemoryIStream(std::string_view bytes, const std::string& name)
      : Imf::IStream(name.c_str()), bytes_(bytes) {}
  bool read(char c[], int n) override {
    if (n < 0 || position_ > bytes_.size() || std::size_t(n) > bytes_.size() - position_)
      throw Iex::InputExc("unexpected end of file");
    std::memcpy(c, bytes_.data() + position_, std::size_t(n));
    position_ += std::size_t(n);
    return position_ < bytes_.size();
  }
  uint64_t tellg() override { return position_; }
  void seekg(uint64_t pos) override { position_ = std::size_t(std::min<uint64_t>(pos, bytes_.size() + 1)); }

 private:
  std::string_view bytes_;
  std::size_t position_ = 0;
};

std::string compressionName(Imf::Compression c) {
  switch (c) {
    case Imf::NO_COMPRESSION:
      return "none";
    case Imf::RLE_COMPRESSION:
      return "rle";
    case Imf::ZIPS_COMPRESSION:
      return "zips";
    case Imf::ZIP_COMPRESSION:
      return "zip";
    case Imf::PIZ_COMPRESSION:
      return "piz";
    case Imf::PXR24_COMPRESSION:
      return "pxr24";
    case Imf::B44_COMPRESSION:
      return "b44";
    case Imf::B44A_COMPRESSION:
      return "b44a";
    case Imf::DWAA_COMPRESSION:
      return "dwaa";
    case Imf::DWAB_COMPRESSION:
      return "dwab";
    default:
      return "unknown";
  }
}

std::string numberText(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", v);
  return text;
}

void collectMetadata(const Imf::Header& header, ImageMetadata& metadata) {
  metadata.clear();
  for (auto it = header.begin(); it != header.end(); ++it) {
    const std::string name = it.name();
    const Imf::Attribute& a = it.attribute();
    const std::string type = a.typeName();
    if (type == "string") {
      metadata[name == "capDate" ? "DateTime" : name] = static_cast<const Imf::StringAttribute&>(a).value();
    } else if (type == "compression") {
      metadata["compression"] = compressionName(static_cast<const Imf::CompressionAttribute&>(a).value());
    } else if (type == "int") {
      metadata[name] = std::to_string(static_cast<const Imf::IntAttribute&>(a).value());
    } else if (type == "float") {
      metadata[name == "pixelAspectRatio" ? "PixelAspectRatio" : name] =
          numberText(static_cast<const Imf::FloatAttribute&>(a).value());
    } else if (type == "double") {
      metadata[name] = numberText(static_cast<const Imf::DoubleAttribute&>(a).value());
    } else if (type == "m44f") {
      const Imath::M44f& m = static_cast<const Imf::M44fAttribute&>(a).value();
      std::string text;
      for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) {
          if (!text.empty()) text += ' ';
          text += numberText(m[r][c]);
        }
      metadata[name] = text;
    } else if (type == "chromaticities") {
      const Imf::Chromaticities& ch = static_cast<const Imf::ChromaticitiesAttribute&>(a).value();
      std::string text;
      for (const Imath::V2f& v : {ch.red, ch.green, ch.blue, ch.white}) {
        if (!text.empty()) text += ' ';
        text += numberText(v.x);
        text += ' ';
        text += numberText(v.y);
      }
      metadata[name] = text;
    }
  }
}

// Metadata read from an EXR holds the header's own attributes too (under
// the names readImage gives them); writing it back must not turn those into
// strings. They, and the multi-part file's structural ones, are left to the
// header; every other key is written as a string.
// OpenEXR's standard attributes that lensrt writes (ImfStandardAttributes.h),
// kept in metadata as text: numbers, 16 for worldToCamera and worldToNDC (Imath's row-vector
// order), 8 for chromaticities (red, green, blue, white x y) and 2 for
// sensorOverallDimensions (mm); lensModel is text. Written with their
// standard types (OpenEXR 3.2's for the lens and sensor ones); text that does
// not parse is left out.
constexpr std::array<const char*, 13> kStandardKeys{"aperture",
                                                    "focus",
                                                    "expTime",
                                                    "isoSpeed",
                                                    "worldToCamera",
                                                    "chromaticities",
                                                    "nominalFocalLength",
                                                    "effectiveFocalLength",
                                                    "sensorPhotositePitch",
                                                    "sensorOverallDimensions",
                                                    "lensModel",
                                                    "entrancePupilOffset",
                                                    "worldToNDC"};

std::vector<float> numbersOf(const std::string& text) {
  std::vector<float> out;
  std::istringstream in(text);
  float v = 0.0f;
  while (in >> v) out.push_back(v);
  if (!in.eof()) out.clear();
  return out;
}

void insertStandardAttribute(Imf::Header& header, const std::string& key, const std::string& value) {
  if (key == "lensModel") {
    header.insert(key, Imf::StringAttribute(value));
    return;
  }
  const std::vector<float> v = numbersOf(value);
  for (const float x : v)
    if (!std::isfinite(x)) return;
  if (key == "worldToCamera" || key == "worldToNDC") {
    if (v.size() != 16) return;
    Imath::M44f m;
    for (int r = 0; r < 4; ++r)
      for (int c = 0; c < 4; ++c) m[r][c] = v[std::size_t(r * 4 + c)];
    if (key == "worldToNDC")
      Imf::addWorldToNDC(header, m);
    else
      Imf::addWorldToCamera(header, m);
  } else if (key == "chromaticities") {
    if (v.size() != 8) return;
    Imf::addChromaticities(header,
                           Imf::Chromaticities({v[0], v[1]}, {v[2], v[3]}, {v[4], v[5]}, {v[6], v[7]}));
  } else if (key == "sensorOverallDimensions") {
    if (v.size() != 2) return;
    header.insert(key, Imf::V2fAttribute(Imath::V2f(v[0], v[1])));
  } else if (v.size() == 1) {
    header.insert(key, Imf::FloatAttribute(v[0]));
  }
}

bool isStandardKey(const std::string& key) {
  for (const char* k : kStandardKeys)
    if (key == k) return true;
  return false;
}

bool isFreeKey(const Imf::Header& header, const std::string& key) {
  if (isStandardKey(key)) return false;
  static constexpr std::array<const char*, 8> kReserved{
      "DateTime", "compression", "PixelAspectRatio", "name", "type", "version", "chunkCount", "tiles"};
  for (const char* reserved : kReserved)
    if (key == reserved) return false;
  const auto existing = header.find(key);
  return existing == header.end() || std::string(existing.attribute().typeName()) == "string";
}

// OpenImageIO's channel order, which lensrt's readers saw before: by layer
// (the name up to its last '.'), then R, G, B, A, X, Y, Z, then by name.
int channelRank(const std::string& suffix) {
  static constexpr std::array<const char*, 7> kFirst{"R", "G", "B", "A", "X", "Y", "Z"};
  for (std::size_t i = 0; i < kFirst.size(); ++i)
    if (suffix.size() == 1 && std::toupper(static_cast<unsigned char>(suffix[0])) == kFirst[i][0])
      return int(i);
  return int(kFirst.size());
}

struct ChannelKey {
  std::string name, layer, suffix;
  int rank;
};

std::vector<std::string> orderedChannels(const Imf::ChannelList& channels, const std::string& name) {
  std::vector<ChannelKey> keys;
  for (auto it = channels.begin(); it != channels.end(); ++it) {
    if (it.channel().xSampling != 1 || it.channel().ySampling != 1)
      throw InputError(name,
                       std::string("channel '") + it.name() + "' is subsampled, which is not supported");
    const std::string full = it.name();
    const std::size_t dot = full.find_last_of('.');
    const std::string layer = dot == std::string::npos ? "" : full.substr(0, dot + 1);
    const std::string suffix = dot == std::string::npos ? full : full.substr(dot + 1);
    keys.push_back({full, layer, suffix, channelRank(suffix)});
  }
  std::sort(keys.begin(), keys.end(), [](const ChannelKey& a, const ChannelKey& b) {
    if (a.layer != b.layer) return a.layer < b.layer;
    if (a.rank != b.rank) return a.rank < b.rank;
    return a.suffix < b.suffix;
  });
  std::vector<std::string> names;
  for (const ChannelKey& k : keys) names.push_back(k.name);
  return names;
}

// OpenEXR allocates each header attribute's value at the size the file
// claims before it reads it: an attribute claiming 1.8 GB in a 600-byte file
// took the fuzzer's whole memory. Walk the header(s) first, with `read(pos,
// n, out)` giving the file's bytes and `size` its length, and refuse sizes
// past the end of the file. OpenEXR 3.1's C++ reader goes by the size field
// only for strings, vectors and unknown types: the others it reads by their
// type (a channel list up to its empty name, a preview by its width and
// height), so a size that lies would put it out of step with this walk (the
// fuzzer hid a 2 GB string behind such an attribute). Those sizes must be
// exactly what the type reads.
std::int64_t fixedAttributeSize(const std::string& type) {
  static const std::map<std::string, std::int64_t> kSizes = {{"box2f", 16},
                                                             {"box2i", 16},
                                                             {"chromaticities", 32},
                                                             {"compression", 1},
                                                             {"deepImageState", 1},
                                                             {"double", 8},
                                                             {"envmap", 1},
                                                             {"float", 4},
                                                             {"int", 4},
                                                             {"keycode", 28},
                                                             {"lineOrder", 1},
                                                             {"m33d", 72},
                                                             {"m33f", 36},
                                                             {"m44d", 128},
                                                             {"m44f", 64},
                                                             {"rational", 8},
                                                             {"tiledesc", 9},
                                                             {"timecode", 8},
                                                             {"v2d", 16},
                                                             {"v2f", 8},
                                                             {"v2i", 8},
                                                             {"v3d", 24},
                                                             {"v3f", 12},
                                                             {"v3i", 12}};
  const auto it = kSizes.find(type);
  return it == kSizes.end() ? -1 : it->second;
}

template <class Read>
void checkHeaderSizes(const Read& read, std::uint64_t size, const std::string& name) {
  unsigned char version[4];
  if (size < 8 || !read(4, 4, version)) return;  // OpenEXR reports short files itself
  const bool multipart = (version[1] & 0x10) != 0;
  std::uint64_t pos = 8;
  // Up to the null byte ending a name; false at the end of the file.
  constexpr std::size_t kMaxName = 255;  // Imf::Name::MAX_LENGTH
  const auto readName = [&](std::string& out) {
    out.clear();
    unsigned char c = 0;
    while (pos < size) {
      if (!read(pos++, 1, &c)) return false;
      if (c == 0) return true;
      if (out.size() == kMaxName)
        throw InputError(name, "a header name is longer than " + std::to_string(kMaxName) + " characters");
      out.push_back(char(c));
    }
    return false;
  };
  const auto readUint32 = [&](std::uint32_t& out) {
    unsigned char b[4];
    if (pos + 4 > size || !read(pos, 4, b)) return false;
    out = std::uint32_t(b[0]) | std::uint32_t(b[1]) << 8 | std::uint32_t(b[2]) << 16 |
          std::uint32_t(b[3]) << 24;
    pos += 4;
    return true;
  };
  std::string attribute, type, channel;
  for (int header = 0; header < 1024; ++header) {
    if (!readName(attribute)) return;
    if (attribute.empty()) return;  // the end of the headers
    for (int count = 0; !attribute.empty(); ++count) {
      std::uint32_t claimed = 0;
      if (count > 100000 || !readName(type) || !readUint32(claimed)) return;
      const std::int64_t bytes = std::int32_t(claimed);
      const auto refuse = [&](const std::string& what) {
        throw InputError(name, "header attribute '" + oneLine(attribute) + "' " + what);
      };
      if (bytes < 0 || std::uint64_t(bytes) > size - pos)
        refuse("claims " + std::to_string(bytes) + " bytes, more than the file has left");
      const std::uint64_t start = pos, end = pos + std::uint64_t(bytes);
      if (const std::int64_t fixed = fixedAttributeSize(type); fixed >= 0) {
        if (bytes != fixed)
          refuse("of type " + oneLine(type) + " has " + std::to_string(bytes) + " bytes, not " +
                 std::to_string(fixed));
      } else if (type == "chlist") {
        // Name, pixel type, pLinear and reserved bytes, x and y sampling.
        for (int n = 0;; ++n) {
          if (n > 100000 || !readName(channel)) return;
          if (channel.empty()) break;
          pos += 16;
          if (pos > end) break;
        }
        if (pos != end)
          refuse("has a channel list that does not fill its " + std::to_string(bytes) + " bytes");
      } else if (type == "preview") {
        std::uint32_t width = 0, height = 0;
        if (bytes < 8 || !readUint32(width) || !readUint32(height) ||
            std::uint64_t(width) * height * 4 != std::uint64_t(bytes) - 8)
          refuse("has a preview image whose size does not match its " + std::to_string(bytes) + " bytes");
      } else if (type == "stringvector") {
        // Each string's own length, within the attribute.
        while (pos < end) {
          std::uint32_t length = 0;
          if (end - pos < 4 || !readUint32(length) || length > end - pos)
            refuse("has a string longer than its " + std::to_string(bytes) + " bytes");
          pos += length;
        }
      } else if (type == "idmanifest") {
        refuse("is an ID manifest, which lensrt does not read");
      }
      pos = start + std::uint64_t(bytes);
      if (!readName(attribute)) return;
    }
    if (!multipart) return;
  }
}

Image decode(Imf::IStream& stream, const std::string& name, ImageMetadata* metadata, std::size_t maxValues) {
  try {
    Imf::InputFile in(stream);
    const Imf::Header& header = in.header();
    const Imath::Box2i data = header.dataWindow(), display = header.displayWindow();
    const std::int64_t width = std::int64_t(data.max.x) - data.min.x + 1;
    const std::int64_t height = std::int64_t(data.max.y) - data.min.y + 1;
    const std::int64_t fullWidth = std::int64_t(display.max.x) - display.min.x + 1;
    const std::int64_t fullHeight = std::int64_t(display.max.y) - display.min.y + 1;
    const std::vector<std::string> channels = orderedChannels(header.channels(), name);
    if (channels.empty()) throw InputError(name, "the image has no channels");
    if (width <= 0 || height <= 0 || width > INT32_MAX || height > INT32_MAX || fullWidth <= 0 ||
        fullHeight <= 0 || fullWidth > INT32_MAX || fullHeight > INT32_MAX)
      throw InputError(name, "the image's data or display window is empty or too large");
    if (double(width) * double(height) * double(channels.size()) > double(maxValues))
      throw InputError(name, "the image is " + std::to_string(width) + "x" + std::to_string(height) +
                                 " with " + std::to_string(channels.size()) + " channels, more than " +
                                 std::to_string(maxValues) + " values");

    // The data window relative to the display window's corner; a file whose
    // display window is the data window is a whole frame.
    const std::int64_t originX = std::int64_t(data.min.x) - display.min.x;
    const std::int64_t originY = std::int64_t(data.min.y) - display.min.y;
    if (originX < INT32_MIN || originY < INT32_MIN || originX + width - 1 > INT32_MAX ||
        originY + height - 1 > INT32_MAX)
      throw InputError(name, "the image's data window lies too far from its display window");
    Image image(int(width), int(height), channels);
    image.originX = int(originX);
    image.originY = int(originY);
    if (fullWidth != width || fullHeight != height || image.originX || image.originY) {
      image.frameWidth = int(fullWidth);
      image.frameHeight = int(fullHeight);
    }
    const std::size_t pixelStride = channels.size() * sizeof(float);
    Imf::FrameBuffer frame;
    for (std::size_t c = 0; c < channels.size(); ++c)
      frame.insert(channels[c], Imf::Slice::Make(Imf::FLOAT, &image.pixels[c], data, pixelStride,
                                                 pixelStride * std::size_t(width)));
    in.setFrameBuffer(frame);
    in.readPixels(data.min.y, data.max.y);
    if (metadata) collectMetadata(header, *metadata);
    return image;
  } catch (const InputError&) {
    throw;
  } catch (const std::exception& e) {
    throw InputError(name, "cannot read image: " + oneLine(e.what()));
  }
}

}  // namespace

bool looksLikeExr(std::string_view head) {
  return head.size() >= 4 && static_cast<unsigned char>(head[0]) == 0x76 &&
         static_cast<unsigned char>(head[1]) == 0x2f && static_cast<unsigned char>(head[2]) == 0x31 &&
         static_cast<unsigned char>(head[3]) == 0x01;
}

std::string encodeExr(const std::string& name, const Image& image, const ImageMetadata& metadata,
                      bool halfFloat) {
  if (std::set<std::string>(image.channels.begin(), image.channels.end()).size() != image.channels.size())
    throw InputError(name, "cannot write an EXR with two channels of the same name");
  try {
    const Imath::Box2i display(Imath::V2i(0, 0), Imath::V2i(image.fullWidth() - 1, image.fullHeight() - 1));
    const Imath::Box2i data(Imath::V2i(image.originX, image.originY),
                            Imath::V2i(image.originX + image.width - 1, image.originY + image.height - 1));
    Imf::Header header(display, data, 1.0f, Imath::V2f(0, 0), 1.0f, Imf::INCREASING_Y, Imf::ZIP_COMPRESSION);
    for (const std::string& channel : image.channels)
      header.channels().insert(channel, Imf::Channel(halfFloat ? Imf::HALF : Imf::FLOAT));
    const auto date = metadata.find("DateTime");
    header.insert("capDate", Imf::StringAttribute(date != metadata.end() ? date->second : captureDate()));
    for (const auto& [key, value] : metadata)
      if (isStandardKey(key))
        insertStandardAttribute(header, key, value);
      else if (isFreeKey(header, key))
        header.insert(key, Imf::StringAttribute(value));

    // OpenEXR writes a frame buffer of the file's pixel type: halves are
    // converted here (Imath's round to nearest even).
    std::vector<Imath::half> halves;
    if (halfFloat) halves.assign(image.pixels.begin(), image.pixels.end());
    const Imf::PixelType type = halfFloat ? Imf::HALF : Imf::FLOAT;
    const std::size_t valueSize = halfFloat ? sizeof(Imath::half) : sizeof(float);
    const char* base = halfFloat ? reinterpret_cast<const char*>(halves.data())
                                 : reinterpret_cast<const char*>(image.pixels.data());
    const std::size_t pixelStride = image.channelCount() * valueSize;
    Imf::FrameBuffer frame;
    for (std::size_t c = 0; c < image.channelCount(); ++c)
      frame.insert(image.channels[c], Imf::Slice::Make(type, base + c * valueSize, data, pixelStride,
                                                       pixelStride * std::size_t(image.width)));
    MemoryOStream stream(name);
    {
      Imf::OutputFile out(stream, header);
      out.setFrameBuffer(frame);
      out.writePixels(image.height);
    }  // the destructor writes the offset table
    return stream.take();
  } catch (const std::exception& e) {
    throw InputError(name, "cannot write: " + oneLine(e.what()));
  }
}

Image readExrFile(const std::filesystem::path& file, ImageMetadata* metadata, std::size_t maxValues) {
  std::unique_ptr<Imf::StdIFStream> stream;
  try {
    stream = std::make_unique<Imf::StdIFStream>(file.c_str());
  } catch (const std::exception& e) {
    throw InputError(file.string(), "cannot open: " + oneLine(e.what()));
  }
  {
    std::ifstream in(file, std::ios::binary);
    in.seekg(0, std::ios::end);
    const auto size = std::uint64_t(std::max<std::streamoff>(0, in.tellg()));
    const auto read = [&](std::uint64_t pos, std::size_t n, unsigned char* out) {
      in.clear();
      in.seekg(std::streamoff(pos));
      return bool(in.read(reinterpret_cast<char*>(out), std::streamsize(n)));
    };
    checkHeaderSizes(read, size, file.string());
  }
  return decode(*stream, file.string(), metadata, maxValues);
}

Image decodeExr(std::string_view bytes, const std::string& name, ImageMetadata* metadata,
                std::size_t maxValues) {
  const auto read = [&](std::uint64_t pos, std::size_t n, unsigned char* out) {
    if (pos > bytes.size() || n > bytes.size() - pos) return false;
    std::memcpy(out, bytes.data() + pos, n);
    return true;
  };
  checkHeaderSizes(read, bytes.size(), name);
  MemoryIStream stream(bytes, name);
  return decode(stream, name, metadata, maxValues);
}

}  // namespace lensrt
