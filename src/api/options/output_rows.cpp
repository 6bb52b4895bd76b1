// Outputs. Rows of the option table (api/option_table.h).
#include <algorithm>
#include <cstdio>

#include "api/options/rows.h"
#include "sensor/mosaic.h"

namespace lensrt {

void addOutputRows(std::vector<Option>& table) {
  const auto add = [&table](Option o) -> Option& { return addRow(table, "output", std::move(o)); };
  {
    Option o =
        row("--aov", "aov", "NAMES",
            "extra EXR channels, comma separated: depth (depth.Z: metres from the camera node's origin to "
            "what the pixel sees, along the ray), z (Z: metres along the camera's viewing axis), normal "
            "(normal.X/Y/Z, "
            "world), albedo (albedo.R/G/B), variance (variance.R/G/B of the pixel mean), crypto_object and "
            "crypto_material (Cryptomatte layers CryptoObject00-02, CryptoMaterial00-02 of glTF node and "
            "material names), object_id (object_id.X: the most covered node index, -1 background), position "
            "(position.X/Y/Z: the world point seen, metres), uv (uv.U/V: its TEXCOORD_0), object_coords "
            "(object_coords.X/Y/Z: the point in its mesh's own frame, metres), flow "
            "(flow.forward.X/Y, flow.backward.X/Y: the image motion to the next and previous frame of "
            "--frame/--frames, or over a still frame's shutter, in pixels, x right, y down), e.g. --aov "
            "depth,variance",
            "depth", PyValue::List);
    o.repeatable = true;
    o.set = [](RenderSpec& s, const std::string& text) {
      std::vector<std::string> names;
      std::size_t start = 0;
      while (start <= text.size()) {
        const std::size_t comma = std::min(text.find(',', start), text.size());
        if (comma > start) names.push_back(text.substr(start, comma - start));
        start = comma + 1;
      }
      const AovSelection more = parseAovs(names);
      s.aovs.depth |= more.depth;
      s.aovs.z |= more.z;
      s.aovs.normal |= more.normal;
      s.aovs.albedo |= more.albedo;
      s.aovs.variance |= more.variance;
      s.aovs.cryptoObject |= more.cryptoObject;
      s.aovs.cryptoMaterial |= more.cryptoMaterial;
      s.aovs.objectId |= more.objectId;
      s.aovs.position |= more.position;
      s.aovs.uv |= more.uv;
      s.aovs.objectCoords |= more.objectCoords;
      s.aovs.flow |= more.flow;
    };
    o.show = [](const RenderSpec& s) {
      std::string names;
      for (const auto& [on, name] :
           {std::pair{s.aovs.depth, "depth"}, std::pair{s.aovs.z, "z"}, std::pair{s.aovs.normal, "normal"},
            std::pair{s.aovs.albedo, "albedo"}, std::pair{s.aovs.variance, "variance"},
            std::pair{s.aovs.cryptoObject, "crypto_object"},
            std::pair{s.aovs.cryptoMaterial, "crypto_material"}, std::pair{s.aovs.objectId, "object_id"},
            std::pair{s.aovs.position, "position"}, std::pair{s.aovs.uv, "uv"},
            std::pair{s.aovs.objectCoords, "object_coords"}, std::pair{s.aovs.flow, "flow"}})
        if (on) {
          if (!names.empty()) names += ',';
          names += name;
        }
      return names;
    };
    add(std::move(o));
  }
  {
    Option o =
        row("--raw", "raw", "FILE.dng",
            "also write the raw file a camera would: the colour filter mosaic (--cfa) as a 16-bit linear "
            "DNG that raw developers read (with --noise on the sensor's DN; else an image value of 1.0 "
            "at the white level 65535), e.g. --raw out/a.dng",
            "a.dng", PyValue::Path);
    o = text(
        std::move(o), [](auto& s) -> auto& { return s.raw.file; });
    o.commands = kRenderCommand;
    o.identity = Identity::Output;
    add(std::move(o));
  }
  {
    Option o = row("--cfa", "cfa", "PATTERN",
                   "the raw file's colour filter pattern: RGGB (default), BGGR, GRBG or GBRG", "BGGR",
                   PyValue::Text);
    o.set = [](RenderSpec& s, const std::string& text) {
      const std::optional<CfaPattern> pattern = parseCfaPattern(text);
      if (!pattern) throw UsageError("--cfa", "expected RGGB, BGGR, GRBG or GBRG, got '" + text + "'");
      s.raw.cfa = *pattern;
    };
    o.show = [](const RenderSpec& s) { return s.raw.cfa.name; };
    o.commands = kRenderCommand;
    o.identity = Identity::Output;
    o.applies = [](const RenderSpec& s) { return !s.raw.file.empty(); };
    o.usedBy = "is the raw file's pattern: it needs --raw FILE.dng";
    add(std::move(o));
  }
  {
    Option o = row("--crop", "crop", "X0,X1,Y0,Y1",
                   "render only pixels X0 <= x < X1, Y0 <= y < Y1 of the frame into an EXR whose data window "
                   "places them (join parts with lensrt merge), e.g. --crop 0,320,0,180",
                   "0,16,0,8", PyValue::List);
    o.set = [](RenderSpec& s, const std::string& text) {
      PixelRegion r;
      char end = 0;
      if (std::sscanf(text.c_str(), "%d,%d,%d,%d%c", &r.x0, &r.x1, &r.y0, &r.y1, &end) != 4)
        throw UsageError("--crop", "expected X0,X1,Y0,Y1 in pixels, e.g. --crop 0,320,0,180");
      if (r.x0 < 0 || r.y0 < 0 || r.x1 <= r.x0 || r.y1 <= r.y0)
        throw UsageError("--crop", "expected 0 <= X0 < X1 and 0 <= Y0 < Y1 (X1, Y1 exclusive), got " + text);
      s.crop = r;
    };
    o.show = [](const RenderSpec& s) { return s.crop ? s.crop->describe() : std::string("frame"); };
    o.commands = kRenderCommand;
    // A part of the frame: parts of one render join (lensrt merge).
    o.identity = Identity::Extent;
    add(std::move(o));
  }
  {
    Option o =
        row("--tile", "", "I/N",
            "render only tile I (from 0) of N: horizontal strips top to bottom, heights differing by at "
            "most a row (for job arrays; join with lensrt merge), e.g. --tile 0/8",
            "0/2", PyValue::Text);
    o.set = [](RenderSpec& s, const std::string& text) {
      int index = 0, count = 0;
      char end = 0;
      if (std::sscanf(text.c_str(), "%d/%d%c", &index, &count, &end) != 2)
        throw UsageError("--tile", "expected I/N (tile I of N, I from 0), e.g. --tile 0/8");
      if (count < 1 || index < 0 || index >= count)
        throw UsageError("--tile", "expected 0 <= I < N, got " + text);
      s.tile = RenderSpec::Strip{index, count};
    };
    o.show = [](const RenderSpec& s) {
      return s.tile ? fmt::format("{}/{}", s.tile->index, s.tile->count) : std::string("frame");
    };
    o.commands = kRenderCommand;
    o.identity = Identity::Extent;
    o.renderKeyword = false;
    add(std::move(o));
  }
}

}  // namespace lensrt
