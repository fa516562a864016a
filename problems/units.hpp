#pragma once
// The units of an answer (problems.hpp): what parse_unit() reads and how it converts to SI.
//
// A unit is written after the value, its factors separated by blanks, '*' or '·' (U+00B7), which
// are all the same: "N m", "N*m", "N·m". It is read in two steps:
//
//   1. The whole text is looked up in base_units(): m, g (the gram: the kilogram is k + g), s, N,
//      N m (also Nm), J, W, Pa, rad, m/s, m/s^2, rad/s, rad/s^2, Hz, g m^2 (kg m^2 is k + g m^2),
//      and the units outside SI deg, deg/s, rpm and 1/s.
//   2. Otherwise, where the text starts with a prefix of si_prefixes() and the rest is a base unit
//      that takes prefixes, the prefix is taken off and scales the base unit: "kJ" is 1e3 J,
//      "kN m" 1e3 N m, "MPa" 1e6 Pa, "km/s" 1e3 m/s, "µm" 1e-6 m. The prefix applies to the first
//      factor of a compound unit, as engineers write it (kN m, not N km).
//
// The prefixes: p n µ m k M G (1e-12 ... 1e9); micro is also written μ (U+03BC) or u, and c
// (1e-2) is taken only where the metre is the first factor (cm, cm/s, cm/s^2). The units outside
// SI (deg, deg/s, rpm, 1/s) take no prefix.
//
// Ambiguity. A text that is a base unit is that unit ("m" is the metre, never a bare milli), and a
// prefix is taken off only where the rest is a base unit: "mm" is m + m, the millimetre; "ms" is
// the millisecond (a metre second would be "m s"); "min" is no unit (no "in"), so a time in
// minutes is refused rather than read as something else. No prefixed form spells a base unit
// (tests/answers_file.test.cpp checks it), so no text has two readings.
//
// The result is the dimension (the SI unit of the problems, "kg m^2", "1/s" for Hz) and the
// factor to SI: parse_unit("mm") = {"m", 1e-3}, parse_unit("kg") = {"kg", 1}.
#include <optional>
#include <string>
#include <vector>

namespace fmbd::problems {

/// A unit as written in an answer: the dimension it measures (its SI unit, e.g. "m/s^2", "N m",
/// "rad") and the factor to SI.
struct Unit {
  std::string si;
  double scale = 1.0;
};

/// The unit of `text` (see above), or std::nullopt when it is not known.
std::optional<Unit> parse_unit(const std::string& text);

/// An SI prefix as it may be written, and its factor.
struct Prefix {
  std::string symbol;  ///< "k", "µ" (UTF-8), "u", ...
  double factor = 1.0;
};

/// Which prefixes a base unit takes.
enum class Prefixes { none, all, all_and_centi };

/// A unit without a prefix: its symbol with single blanks between factors, its dimension and
/// factor to SI, and the prefixes it takes.
struct BaseUnit {
  std::string symbol;
  Unit unit;
  Prefixes prefixes = Prefixes::none;
};

/// p, n, µ, μ, u, m, c, k, M, G.
const std::vector<Prefix>& si_prefixes();
/// The units without a prefix (see above).
const std::vector<BaseUnit>& base_units();

}  // namespace fmbd::problems
