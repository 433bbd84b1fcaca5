#include "optics/import/patent_table.h"

#include <string>

#include "optics/import/patent_reader.h"
#include "optics/import/patent_text.h"

namespace lenslab::optics {

using patent::lowerAscii;

const char* patentColumnLabel(PatentColumn column) {
  switch (column) {
    case PatentColumn::Surface:
      return "surface";
    case PatentColumn::Radius:
      return "r";
    case PatentColumn::Thickness:
      return "d";
    case PatentColumn::IndexD:
      return "n_d";
    case PatentColumn::AbbeD:
      return "V_d";
    case PatentColumn::Ignored:
      return "ignored";
  }
  return "ignored";
}

bool isPatentTablePath(const std::string& path) {
  if (path.size() < 4) return false;
  return lowerAscii(path.substr(path.size() - 4)) == ".txt";
}

PatentTableResult readPatentTable(std::string_view text, const std::string& fileName,
                                  const std::vector<std::optional<PatentColumn>>& columnOverrides) {
  patent::PatentReader reader(withoutByteOrderMark(text), fileName, columnOverrides);
  return reader.read();
}

LensFileResult parsePatentTableText(std::string_view text, const std::string& fileName) {
  return readPatentTable(text, fileName).lens;
}

}  // namespace lenslab::optics
