#pragma once
// A patent's numerical example, pasted as text (or saved as a .txt file): the surface table
// (r, d, n_d, ν_d), the aspheric data and the header values (f, Fno, ω, image height, back
// focus), in the conventions US, JP, EP and WO publications print them (docs/file-formats.md,
// "Patent tables (.txt)"):
// - a heading row naming the columns (`r`, `d`, `nd`/`Nd`/`n`, `νd`/`vd`/`ν`/`Vd`, a surface
//   number column, in any order; unknown headings are ignored), separated by spaces or tabs;
//   or one line per surface written as equations (`R1 = … D1 = … N1 = … ν1 = …`);
// - `∞`, `INF`, `inf`, `infinity` for a flat surface;
// - the stop as a row of its own marked `(Stop)`, `STO`, `S` or `aperture stop`, or such a mark
//   on a refracting surface's row (the stop is then inserted at that vertex, stop_on_surface.h);
// - aspheric surfaces marked `*` before or after their number (or after the radius), and a block
//   of `K`/`κ` and `A4`, `A6`… (or letters `A`, `B`, `C`… whose powers the sag formula printed
//   with them gives; r⁴, r⁶, r⁸… without one), in E, e, D, `×10^-6` and `x10-6` notation.
// The last row's d is the film distance; a table whose last row has none uses the stated back
// focus. Glasses are model glasses from n_d and ν_d. Every problem is an error at file:line:column.
//
// What the reader understood (the rows, the aspheric data, the header values and the meaning it
// gave each column) is kept in PatentTable, for the paste dialog to show, and a column's meaning
// can be overridden and the text read again.

#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "optics/lens_file.h"

namespace lenslab::optics {

// What a column of the table holds.
enum class PatentColumn { Ignored, Surface, Radius, Thickness, IndexD, AbbeD };
// "surface", "r", "d", "n_d", "V_d", "ignored" (the dialog's combo labels; ASCII, as the
// viewer's font has no Greek).
const char* patentColumnLabel(PatentColumn column);
inline constexpr PatentColumn kPatentColumns[] = {PatentColumn::Surface,   PatentColumn::Radius,
                                                  PatentColumn::Thickness, PatentColumn::IndexD,
                                                  PatentColumn::AbbeD,     PatentColumn::Ignored};

// One column (or, in the equation layout, one key such as `R` or `N`) as the reader saw it.
struct PatentTableColumn {
  std::string heading;  // as printed (UTF-8)
  PatentColumn meaning = PatentColumn::Ignored;
  bool overridden = false;  // the meaning came from the caller, not from the heading
};

// One surface row as understood.
struct PatentTableRow {
  int line = 0;                       // 1-based line of the text
  std::string label;                  // the surface cell as printed ("6*", "STO", "7(Stop)")
  int surfaceNumber = 0;              // the number the aspheric data refer to it by
  double radiusMm = 0.0;              // kFlatRadius for ∞
  std::optional<double> thicknessMm;  // empty on a last row that gives none
  std::optional<double> indexD;       // empty: air
  std::optional<double> abbeD;
  bool stop = false;
  bool aspheric = false;  // marked `*`
};

// One surface's aspheric data as understood.
struct PatentAsphere {
  int line = 0;  // where its surface is named
  int surfaceNumber = 0;
  double conic = 0.0;  // the standard conic constant k (0 = sphere), after any κ conversion
  std::vector<std::pair<int, double>> terms;  // (power, coefficient), in the order printed
};

// A header value and the line it was found on.
struct PatentHeaderValue {
  double value = 0.0;
  int line = 0;
};
struct PatentHeader {
  std::optional<PatentHeaderValue> focalLengthMm;
  std::optional<PatentHeaderValue> fNumber;
  std::optional<PatentHeaderValue> halfFieldDeg;  // ω (half of a printed 2ω)
  std::optional<PatentHeaderValue> imageHeightMm;
  std::optional<PatentHeaderValue> backFocusMm;
};

struct PatentTable {
  bool equationLayout = false;  // `R1 = …  D1 = …` lines rather than columns
  int headingLine = 0;          // 0: no heading row (the columns were taken in the usual order)
  std::vector<PatentTableColumn> columns;
  std::vector<PatentTableRow> rows;
  std::vector<PatentAsphere> aspheres;
  PatentHeader header;
  // How the aspheric data were read: "K = k", "κ = k + 1 (sag formula 1 − κ h²/R²)", and the
  // powers of lettered coefficients ("A B C D → r⁴ r⁶ r⁸ r¹⁰, from the sag formula").
  std::vector<std::string> asphericConventions;
  // The film distance and where it came from ("last row's d", "back focus").
  std::optional<double> filmDistanceMm;
  std::string filmDistanceFrom;
};

struct PatentTableResult {
  PatentTable table;    // what was understood, also when the lens has errors
  LensFileResult lens;  // the lens, or the errors at file:line:column
};

// Reads a numerical example. `columnOverrides`, when not empty, gives a meaning per column (in
// PatentTable::columns' order) that replaces the one the headings suggest; std::nullopt keeps it.
PatentTableResult readPatentTable(
    std::string_view text, const std::string& fileName,
    const std::vector<std::optional<PatentColumn>>& columnOverrides = {});

// readPatentTable's lens alone: what readLensFile calls for a .txt file.
LensFileResult parsePatentTableText(std::string_view text, const std::string& fileName);

// Whether a path names a patent table (a .txt file, in any case).
bool isPatentTablePath(const std::string& path);

}  // namespace lenslab::optics
