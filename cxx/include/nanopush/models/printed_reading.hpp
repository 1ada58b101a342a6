// The readings of the printed friction law: each of the four slips of the thesis' eqs
// (3.45)-(3.50) as printed or corrected (docs/rough.md; errata F1-F3 and erratum 3).
#pragma once
#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <utility>

#include "nanopush/numerics/names.hpp"

namespace nanopush {

/// A reading of the four slips of eqs (3.45)-(3.50) (docs/rough.md, errata F1-F3 and erratum 3):
/// each switch true = as printed, false = corrected. The default is the literal reading the
/// `printed` law has always used: F1 and F3 as printed, C4 with squares (evaluated in nm), and
/// eq 3.50 corrected.
struct PrintedReading {
  bool fy_sign = true;     ///< F1: (3.46) fy' with the printed sign (false: the sign of 3.43)
  bool omega_sign = true;  ///< F3: (3.47) without sign(theta-dot) (false: mf times sign(theta-dot))
  bool c4_squares = true;  ///< F2: (3.48) C4 with squares, lengths in nm (false: cubes, consistent)
  bool eq3_50 = false;     ///< erratum 3: fy = fx' sin(theta) - fy' cos(theta) as printed (false: +)
  friend bool operator==(const PrintedReading&, const PrintedReading&) = default;
};
/// How eq 3.48's C4 is read (surface.printed.c4): with squares, lengths in nm, as printed (F2),
/// or with cubes, dimensionally consistent.
enum class PrintedC4 { squares_nm, cubes };
NANOPUSH_NAMES(PrintedC4, {PrintedC4::squares_nm, "squares_nm"}, {PrintedC4::cubes, "cubes"});

/// The 16 readings in a fixed order: index bit 0 corrects F1, bit 1 F3, bit 2 takes cubes in C4,
/// bit 3 prints eq 3.50; index 0 is the literal reading (PrintedReading{}).
PrintedReading printed_reading(int index);
int printed_reading_index(const PrintedReading& r);
/// The named readings (surface.printed.reading), in the order messages list them: literal
/// (index 0, the law as it has always run), as_drawn (14: F1 printed, F3 corrected, cubes in C4,
/// eq 3.50 printed: the reading the thesis' Figs 3.18 and 3.29 support best, scored by the
/// `printed-readings` reproduce step, docs/rough.md), corrected (7: F1-F3 corrected, the Coulomb
/// wrench of the thesis law).
inline constexpr std::array<std::pair<std::string_view, int>, 3> kPrintedReadingNames{
    {{"literal", 0}, {"as_drawn", 14}, {"corrected", 7}}};
std::optional<PrintedReading> printed_reading_named(std::string_view name);
/// The name of a named reading, or "" for the others.
std::string_view printed_reading_name(const PrintedReading& r);
/// "F1 printed, F3 printed, C4 squares (nm), 3.50 corrected": the switches in words.
std::string printed_reading_text(const PrintedReading& r);

}  // namespace nanopush
