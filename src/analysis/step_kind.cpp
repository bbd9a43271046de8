#include "analysis/step_kind.hpp"

#include <algorithm>
#include <array>

#include "analysis/delimited_text.hpp"

namespace dilatant::analysis {
namespace {

bool contains_any(std::string_view text, std::initializer_list<std::string_view> words) {
  return std::any_of(words.begin(), words.end(),
                     [&](std::string_view w) { return text.find(w) != std::string_view::npos; });
}

// A whole word of the name: "rest" in "Rest 60 s", not in "interest".
bool has_word(std::string_view text, std::string_view word) {
  for (auto at = text.find(word); at != std::string_view::npos; at = text.find(word, at + 1)) {
    const auto letter = [&](std::size_t k) {
      return k < text.size() && ((text[k] >= 'a' && text[k] <= 'z') || (text[k] & 0x80));
    };
    if ((at == 0 || !letter(at - 1)) && !letter(at + word.size())) return true;
  }
  return false;
}

}  // namespace

std::string_view step_kind_name(StepKind kind) {
  switch (kind) {
    case StepKind::FlowCurve:
      return "flow curve";
    case StepKind::Oscillation:
      return "oscillation";
    case StepKind::Hold:
      return "hold";
    case StepKind::Other:
      return "other";
  }
  return "";
}

std::optional<StepKind> kind_from_name(std::string_view name) {
  const std::string n = lower_case(name);
  if (contains_any(n, {"oscillat", "oszillat", "amplitude", "amplitud", "frequency", "frequenz",
                       "fr\xC3\xA9quence", "frequence", "strain sweep", "laos", "saos"}))
    return StepKind::Oscillation;
  if (contains_any(n, {"peak hold", "pre shear", "pre-shear", "preshear", "pre_shear",
                       "conditioning", "equilibrat", "vorscher",
                       "pr\xC3\xA9"
                       "cisaillement",
                       "precisaillement", "relaxation", "recovery", "erholung"}) ||
      has_word(n, "hold") || has_word(n, "rest") || has_word(n, "creep") || has_word(n, "ruhe") ||
      has_word(n, "repos") || has_word(n, "soak"))
    return StepKind::Hold;
  if (contains_any(n, {"flow", "viscometry", "ramp", "flie\xC3\x9f", "fliess", "rampe",
                       "\xC3\xA9"
                       "coulement",
                       "ecoulement", "viscosit"}))
    return StepKind::FlowCurve;
  return std::nullopt;
}

bool has_oscillation_columns(const std::vector<std::string>& headings) {
  return std::any_of(headings.begin(), headings.end(), [](const std::string& h) {
    const std::string n = lower_case(h);
    return contains_any(
               n, {"storage modulus", "loss modulus", "phase angle", "tan(delta)", "tan delta",
                   "complex modulus", "speichermodul", "verlustmodul", "phasenwinkel",
                   "module de conservation", "module de perte", "angle de phase"}) ||
           n.starts_with("g'") || n.starts_with("g''") || n.starts_with("g\"");
  });
}

}  // namespace dilatant::analysis
