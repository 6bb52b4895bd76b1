// The scene file and its moment (Python: the Scene constructor's). Rows of the option table
// (api/option_table.h).
#include "api/options/rows.h"

namespace lensrt {

void addSceneRows(std::vector<Option>& table) {
  const auto add = [&table](Option o) -> Option& { return addRow(table, "scene", std::move(o)); };
  {
    Option& o = add(integer(
        row("--scene-index", "scene_index", "N",
            "which glTF scene to render (0-based; default: the file's default scene), e.g. "
            "--scene-index 1",
            "0", PyValue::Integer),
        [](auto& s) -> auto& { return s.scene.sceneIndex; }, 0, 1 << 20, "0-based"));
    o.renderKeyword = false;
  }
  {
    Option o = row("--allow-external-files", "allow_external_files", "",
                   "let the scene read files outside its folder (absolute paths, '..', symbolic links out of "
                   "it), naming each one read; only for scenes you trust (default: off, or "
                   "LENSRT_ALLOW_EXTERNAL_FILES=1)",
                   "1", PyValue::Switch);
    o.isFlag = true;
    o.environmentVariable = "LENSRT_ALLOW_EXTERNAL_FILES";
    o.renderKeyword = false;
    o.identity = Identity::None;  // what the scene reads is in its digest
    o.set = [](RenderSpec& s, const std::string& text) { s.scene.access.allowExternalFiles = text == "1"; };
    o.show = [](const RenderSpec& s) { return std::string(s.scene.access.allowExternalFiles ? "1" : "0"); };
    add(std::move(o));
  }
  {
    Option o = row("--max-texture-memory", "max_texture_memory", "MIB",
                   "MiB the scene's textures may take as held for rendering (16 bytes a texel), e.g. "
                   "--max-texture-memory 4096 (default: half this machine's memory)",
                   "4096", PyValue::Integer);
    o.set = [](RenderSpec& s, const std::string& text) {
      s.scene.access.maxTextureMiB =
          parseUnsignedIn("--max-texture-memory", text, 1, std::uint64_t{1} << 40, "MiB");
    };
    o.show = [](const RenderSpec& s) { return std::to_string(s.scene.access.maxTextureMiB); };
    o.renderKeyword = false;
    o.identity = Identity::None;  // a limit: a render it allows is the same render
    add(std::move(o));
  }
  {
    Option o = row("--time", "time", "SECONDS",
                   "when the shutter opens, in seconds of the glTF's animations, e.g. --time 1.5 (default 0)",
                   "1.5", PyValue::Number);
    o.set = [](RenderSpec& s, const std::string& text) {
      s.time.seconds = parseNumberIn("--time", text, -1e9, 1e9, "seconds");
    };
    o.show = [](const RenderSpec& s) { return numberText(s.time.atSeconds()); };
    o.renderKeyword = false;
    add(std::move(o));
  }
  {
    Option o = row("--frame", "", "N", "the same counted in frames of --fps, e.g. --frame 36", "36",
                   PyValue::Integer);
    o.set = [](RenderSpec& s, const std::string& text) {
      s.time.frame = int(parseIntegerIn("--frame", text, -1000000000, 1000000000, "a frame number"));
    };
    o.show = [](const RenderSpec& s) { return numberText(s.time.atSeconds()); };
    o.renderKeyword = false;
    add(std::move(o));
  }
  {
    Option& o = add(number(
        row("--fps", "", "F", "frames per second for --frame, e.g. --fps 30 (default 24)", "30",
            PyValue::Number),
        [](auto& s) -> auto& { return s.time.fps; }, 1e-3, 1e6, "frames per second"));
    o.renderKeyword = false;
    o.show = [](const RenderSpec& s) { return numberText(s.time.fps); };
    // Alone it changes nothing; with --frame the moment changes, which --frame's row shows.
    o.identity = Identity::None;
  }
  {
    Option& o = add(text(
        row("--animation", "animation", "NAME|INDEX",
            "which glTF animation plays: a name or a 0-based index (default: all of them)", "0",
            PyValue::NumberOrText),
        [](auto& s) -> auto& { return s.time.animation; }));
    o.renderKeyword = false;
  }
  {
    Option o = row("--flow-step", "flow_step", "SECONDS",
                   "--aov flow's neighbouring frames: the scene this many seconds after and before (the "
                   "next and previous frame), e.g. --flow-step 0.04 (default: --frames' step, 1/fps with "
                   "--frame, else the motion over the shutter)",
                   "0.04", PyValue::Number);
    o.set = [](RenderSpec& s, const std::string& text) {
      s.time.flowStepSeconds = parseNumberIn("--flow-step", text, 1e-9, 1e9, "seconds");
    };
    o.show = [](const RenderSpec& s) { return numberText(s.time.flowStepSeconds); };
    o.applies = [](const RenderSpec& s) { return s.aovs.flow; };
    o.usedBy = "needs --aov flow";
    add(std::move(o));
  }
}

}  // namespace lensrt
