#include "units.hpp"

#include <sstream>

namespace fmbd::problems {

namespace {

constexpr double kPi = 3.14159265358979323846;

// The factors of `text` joined with one space: blanks, '*' and '·' separate them.
std::string normalised(const std::string& text) {
  std::string spaced;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text.compare(i, 2, "\xC2\xB7") == 0) {  // U+00B7 MIDDLE DOT
      spaced += ' ';
      ++i;
    } else {
      spaced += text[i] == '*' ? ' ' : text[i];
    }
  }
  std::string key;
  std::istringstream parts(spaced);
  for (std::string word; parts >> word;) key += (key.empty() ? "" : " ") + word;
  return key;
}

const BaseUnit* find_base(const std::string& symbol) {
  for (const BaseUnit& base : base_units()) {
    if (base.symbol == symbol) return &base;
  }
  return nullptr;
}

}  // namespace

const std::vector<Prefix>& si_prefixes() {
  static const std::vector<Prefix> prefixes = {
      {"p", 1e-12}, {"n", 1e-9},          {"\xC2\xB5", 1e-6}, {"\xCE\xBC", 1e-6}, {"u", 1e-6},
      {"m", 1e-3},  {"c", 1e-2},          {"k", 1e3},         {"M", 1e6},         {"G", 1e9},
  };
  return prefixes;
}

const std::vector<BaseUnit>& base_units() {
  using P = Prefixes;
  static const std::vector<BaseUnit> units = {
      {"m", {"m", 1}, P::all_and_centi},
      {"g", {"kg", 1e-3}, P::all},
      {"s", {"s", 1}, P::all},
      {"N", {"N", 1}, P::all},
      {"N m", {"N m", 1}, P::all},
      {"Nm", {"N m", 1}, P::all},
      {"J", {"J", 1}, P::all},
      {"W", {"W", 1}, P::all},
      {"Pa", {"Pa", 1}, P::all},
      {"rad", {"rad", 1}, P::all},
      {"deg", {"rad", kPi / 180}, P::none},
      {"m/s", {"m/s", 1}, P::all_and_centi},
      {"m/s^2", {"m/s^2", 1}, P::all_and_centi},
      {"rad/s", {"rad/s", 1}, P::all},
      {"deg/s", {"rad/s", kPi / 180}, P::none},
      {"rpm", {"rad/s", 2 * kPi / 60}, P::none},
      {"rad/s^2", {"rad/s^2", 1}, P::all},
      {"Hz", {"1/s", 1}, P::all},
      {"1/s", {"1/s", 1}, P::none},
      {"g m^2", {"kg m^2", 1e-3}, P::all},
  };
  return units;
}

std::optional<Unit> parse_unit(const std::string& text) {
  const std::string key = normalised(text);
  if (const BaseUnit* base = find_base(key)) return base->unit;
  for (const Prefix& prefix : si_prefixes()) {
    if (key.size() <= prefix.symbol.size() || key.compare(0, prefix.symbol.size(), prefix.symbol) != 0) continue;
    const BaseUnit* base = find_base(key.substr(prefix.symbol.size()));
    if (base == nullptr || base->prefixes == Prefixes::none) continue;
    if (prefix.symbol == "c" && base->prefixes != Prefixes::all_and_centi) continue;
    return Unit{base->unit.si, prefix.factor * base->unit.scale};
  }
  return std::nullopt;
}

}  // namespace fmbd::problems
