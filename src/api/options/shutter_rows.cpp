// The shutter (api/shutter_spec.h). Rows of the option table (api/option_table.h).
#include <optional>

#include "api/options/rows.h"

namespace lensrt {

void addShutterRows(std::vector<Option>& table) {
  const auto add = [&table](Option o) -> Option& { return addRow(table, "shutter", std::move(o)); };
  {
    Option o = row("--shutter", "shutter", "SECONDS",
                   "shutter time in seconds, e.g. 1/125 (default 1/100): the exposure under --exposure "
                   "physical, and the motion blur of an animated scene (0: an instant)",
                   "1/250", PyValue::NumberOrText);
    o.set = [](RenderSpec& s, const std::string& text) {
      s.shutter.seconds = parseSeconds("--shutter", text);
    };
    o.show = [](const RenderSpec& s) { return numberText(s.shutter.shutterSeconds()); };
    add(std::move(o));
  }
  {
    Option o = row("--shutter-curve", "shutter_curve", "box|trapezoid:F",
                   "how the shutter opens: box (at once; default) or trapezoid:F (a leaf shutter taking the "
                   "share F <= 0.5 of --shutter to open, and again to close), e.g. --shutter-curve "
                   "trapezoid:0.2",
                   "trapezoid:0.2", PyValue::Text);
    o.set = [](RenderSpec& s, const std::string& text) {
      if (text == "box") {
        s.shutter.rampFraction = 0;
        return;
      }
      const std::string prefix = "trapezoid:";
      std::optional<double> f;
      if (text.starts_with(prefix)) {
        try {
          f = parseNumberFrom("--shutter-curve", text.substr(prefix.size()), 0.0, "", true);
        } catch (const UsageError&) {
        }
      }
      if (!f || *f > 0.5)
        throw UsageError(
            "--shutter-curve",
            fmt::format("expected box or trapezoid:F with 0 < F <= 0.5 (the share of the interval the "
                        "shutter takes to open, and to close), got '{}'",
                        text));
      s.shutter.rampFraction = *f;
    };
    o.show = [](const RenderSpec& s) {
      return s.shutter.rampFraction > 0 ? "trapezoid:" + numberText(s.shutter.rampFraction)
                                        : std::string("box");
    };
    add(std::move(o));
  }
  {
    Option o = row("--rolling-shutter", "rolling_shutter", "SECONDS",
                   "a CMOS rolling shutter: each row starts its exposure later by READOUT x row / rows, e.g. "
                   "--rolling-shutter 1/30 (default: a global shutter)",
                   "1/30", PyValue::NumberOrText);
    o.set = [](RenderSpec& s, const std::string& text) {
      s.shutter.readoutSeconds = parseSeconds("--rolling-shutter", text);
    };
    o.show = [](const RenderSpec& s) { return numberText(s.shutter.readoutSeconds); };
    add(std::move(o));
  }
  {
    using R = ShutterTiming::Readout;
    Option& o = add(choice(
        row("--readout", "readout", "DIRECTION",
            "the rolling shutter's direction in the image as seen: top-down (default), "
            "bottom-up, left-right or right-left",
            "left-right", PyValue::Text),
        [](auto& s) -> auto& { return s.shutter.readout; },
        std::vector<std::pair<std::string, R>>{{"top-down", R::TopDown},
                                               {"bottom-up", R::BottomUp},
                                               {"left-right", R::LeftRight},
                                               {"right-left", R::RightLeft}}));
    o.applies = [](const RenderSpec& s) { return s.shutter.readoutSeconds > 0; };
    o.usedBy = "is the direction of a rolling shutter: it needs --rolling-shutter SECONDS";
  }
}

}  // namespace lensrt
