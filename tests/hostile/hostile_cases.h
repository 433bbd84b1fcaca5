#pragma once
// The bad-input catalogue (issue 24): every case is a lens or scene file that must be refused
// with a clear message at its place, a non-zero exit and no output. The small cases are files in
// tests/hostile/, each saying in its first comment lines what it is ("# expect: TEXT" and
// "# at: LINE:COLUMN"); the huge ones (10 MB lines, 3 million numbers, a 10-million-digit number,
// 10,000 surfaces, a 1,000-deep Include chain, a PNG that claims 100000 x 100000 pixels) and the
// NaN/inf sweeps are written here at run time into a scratch directory, not committed.

#include <cctype>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "support/hostile_patent_table.h"
#include "support/run_process.h"

namespace lenslab::hostile {

struct HostileCase {
  std::filesystem::path file;
  bool scene = false;          // a .pbrt (lenslab render), else a lens file (info, focus)
  std::string expect;          // a part of the error message
  std::string at;              // "LINE:COLUMN" where the error must be reported; empty: see place
  std::string placeText;       // when `at` is empty: what names the place (default: the file name)
  std::string extraArguments;  // for lenslab render, after the scene
};

// What the message must hold to say where: "file:LINE:COLUMN:", or the file, or the option.
inline std::string placeOf(const HostileCase& hostile) {
  const std::string name = hostile.file.filename().string();
  if (!hostile.at.empty()) return name + ":" + hostile.at + ":";
  return hostile.placeText.empty() ? name : hostile.placeText;
}

inline void writeText(const std::filesystem::path& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

// "# expect: ..." and "# at: ..." from a committed case's leading comments.
inline HostileCase committedCase(const std::filesystem::path& path) {
  HostileCase result;
  result.file = path;
  result.scene = path.extension() == ".pbrt";
  std::ifstream input(path);
  std::string line;
  while (std::getline(input, line) && line.rfind("#", 0) == 0) {
    if (line.rfind("# expect: ", 0) == 0) result.expect = line.substr(10);
    if (line.rfind("# at: ", 0) == 0) result.at = line.substr(6);
  }
  return result;
}

// Bytes that are no text: a fixed linear congruential sequence, so every run tests the same ones.
inline std::string binaryGarbage(std::size_t size) {
  std::string bytes(size, '\0');
  std::uint32_t state = 24;
  for (char& byte : bytes) {
    state = state * 1664525u + 1013904223u;
    byte = static_cast<char>(state >> 24);
  }
  return bytes;
}

// The 8-byte signature, then an IHDR chunk that claims `side` x `side` RGB pixels, and no data:
// what a decoder sees before it would allocate the picture. The CRC is computed here (PNG's
// CRC-32, polynomial 0xEDB88320) so that the header is valid and only its size is hostile.
inline std::string pngClaiming(std::uint32_t side) {
  const auto crc32 = [](const std::string& bytes) {
    std::uint32_t crc = 0xFFFFFFFFu;
    for (unsigned char byte : bytes) {
      crc ^= byte;
      for (int bit = 0; bit < 8; ++bit) crc = (crc >> 1) ^ (0xEDB88320u & (0u - (crc & 1u)));
    }
    return crc ^ 0xFFFFFFFFu;
  };
  const auto bigEndian = [](std::uint32_t value) {
    return std::string{static_cast<char>(value >> 24), static_cast<char>(value >> 16),
                       static_cast<char>(value >> 8), static_cast<char>(value)};
  };
  const std::string body =
      "IHDR" + bigEndian(side) + bigEndian(side) + std::string("\x08\x02\0\0\0", 5);
  const std::string end = "IEND";
  return std::string("\x89PNG\r\n\x1a\n", 8) + bigEndian(13) + body + bigEndian(crc32(body)) +
         bigEndian(0) + end + bigEndian(crc32(end));
}

// A number token of a scene or lens file: where it starts (1-based line and byte column) and its
// extent in the text.
struct NumberToken {
  std::size_t offset = 0, length = 0;
  int line = 0, column = 0;
};

// The numbers of `text` outside comments and quoted strings, found by a scan of its own (not the
// product's tokenizer): a digit, sign or point that starts a token.
inline std::vector<NumberToken> numberTokens(const std::string& text) {
  std::vector<NumberToken> numbers;
  int line = 1, column = 1;
  bool inComment = false, inString = false;
  for (std::size_t i = 0; i < text.size();) {
    const char c = text[i];
    if (c == '\n') {
      inComment = inString = false;
      ++line, column = 1, ++i;
      continue;
    }
    const bool startsToken =
        i == 0 || std::isspace(static_cast<unsigned char>(text[i - 1])) || text[i - 1] == '[';
    if (!inComment && !inString && startsToken &&
        (std::isdigit(static_cast<unsigned char>(c)) || c == '-' || c == '.')) {
      std::size_t end = i;
      while (end < text.size() && !std::isspace(static_cast<unsigned char>(text[end])) &&
             text[end] != ']') {
        ++end;
      }
      numbers.push_back({i, end - i, line, column});
      column += static_cast<int>(end - i);
      i = end;
      continue;
    }
    if (!inString && c == '#') inComment = true;
    if (!inComment && c == '"') inString = !inString;
    ++column, ++i;
  }
  return numbers;
}

// Every case, written into `directory` (the committed ones copied there, so that all outputs
// and every file a case names stay in one scratch place).
inline std::vector<HostileCase> buildCases(const std::filesystem::path& directory) {
  namespace fs = std::filesystem;
  std::vector<HostileCase> cases;
  const fs::path source = fs::path(LENSLAB_SOURCE_DIR) / "tests" / "hostile";
  for (const auto& entry : fs::directory_iterator(source)) {
    const fs::path path = entry.path();
    if (path.extension() != ".pbrt" && path.extension() != ".dat" && path.extension() != ".zmx")
      continue;
    fs::copy_file(path, directory / path.filename(), fs::copy_options::overwrite_existing);
    cases.push_back(committedCase(directory / path.filename()));
  }
  writeText(directory / "claims-100000-pixels.png", pngClaiming(100000));

  const std::string camera =
      "LookAt 0 1 4  0 0.3 0  0 1 0\nCamera \"perspective\" \"float fov\" [40]\n"
      "Film \"image\" \"integer xresolution\" [32] \"integer yresolution\" [24]\nWorldBegin\n"
      "LightSource \"distant\" \"point from\" [1 4 2] \"rgb L\" [3 3 3]\n";
  const auto scene = [&](const std::string& name, const std::string& text, std::string expect,
                         std::string at) {
    writeText(directory / name, text);
    cases.push_back({directory / name, true, std::move(expect), std::move(at), "", ""});
  };
  scene("garbage.pbrt", binaryGarbage(4096), "", "1:1");
  scene("ten-megabyte-line.pbrt", camera + std::string(10'000'000, 'x') + "\nWorldEnd\n",
        "(10000000 characters)", "6:1");
  scene("ten-megabyte-name.pbrt",
        camera + "Shape \"" + std::string(10'000'000, 's') + "\"\nWorldEnd\n",
        "the scene has no shapes", "");  // after a warning that quotes 40 of the name's letters
  std::string threeMillion;
  for (int i = 0; i < 3'000'000; ++i) threeMillion += " 0.5";
  scene("three-million-numbers.pbrt",
        camera + "Shape \"sphere\" \"float radius\" [" + threeMillion + " ]\nWorldEnd\n",
        "takes 1 value, but 3000000 are given", "6:16");
  scene("ten-million-digits.pbrt",
        camera + "Shape \"sphere\" \"float radius\" [" + std::string(10'000'000, '7') +
            "]\nWorldEnd\n",
        "(10000000 characters)", "6:32");
  // c0.pbrt includes c1.pbrt, ..., c999.pbrt: a thousand files deep.
  fs::create_directories(directory / "chain");
  for (int i = 0; i < 1000; ++i) {
    // Appended, not a chain of operator+: GCC 12 flags that with a false -Wrestrict positive.
    std::string text = "Shape \"sphere\" \"float radius\" [1]\n";
    if (i < 999) {
      text = "Include \"c";
      text += std::to_string(i + 1);
      text += ".pbrt\"\n";
    }
    std::string name = "c";
    name += std::to_string(i);
    name += ".pbrt";
    writeText(directory / "chain" / name, text);
  }
  scene("include-chain.pbrt", camera + "Include \"chain/c0.pbrt\"\nWorldEnd\n",
        "Include nested too deeply", "");
  cases.back().placeText = "chain/c31.pbrt:1:9:";  // the Include that went one file too deep
  // A valid scene asked for at an absurd size on the command line.
  scene("valid.pbrt", camera + "Shape \"sphere\" \"float radius\" [0.5]\nWorldEnd\n",
        "size 100000x100000 is out of range", "");
  cases.back().extraArguments = "--resolution 100000x100000";
  cases.back().placeText = "--resolution";

  const std::string lensText =
      testing::readWholeFile(fs::path(LENSLAB_SOURCE_DIR) / "lenses" / "dgauss-50mm.dat");
  const auto lens = [&](const std::string& name, const std::string& text, std::string expect,
                        std::string at) {
    writeText(directory / name, text);
    cases.push_back({directory / name, false, std::move(expect), std::move(at), "", ""});
  };
  lens("garbage.dat", binaryGarbage(4096), "binary file", "");
  // OpticStudio files (import/zemax_file.h): UTF-16 cut to an odd number of bytes (the error
  // stands where the text stops: line 3, after "SUR" and half of "F"), an empty
  // file, and 100,000 surfaces.
  std::string utf16 = "\xFF\xFE";
  for (const char c : std::string("SURF 0\r\n  DISZ INFINITY\r\nSURF 1\r\n")) {
    utf16 += c;
    utf16 += '\0';
  }
  utf16.resize(utf16.size() - 9);  // "SURF 1\r\n" less 4 units and a half
  lens("utf16-odd-byte-count.zmx", utf16, "odd number of bytes", "3:4");
  lens("empty.zmx", "", "empty file", "1:1");
  std::string surfaces;
  for (int i = 0; i < 100'000; ++i) {
    surfaces += "SURF ";
    surfaces += std::to_string(i);
    surfaces += "\n  CURV 0.01\n  DISZ 1\n  DIAM 5\n";
  }
  lens("hundred-thousand-surfaces.zmx", surfaces, "too many surfaces",
       std::to_string(258 * 4 + 1) + ":6");
  // Patent tables (import/patent_table.h): a valid f/4 table with one thing wrong each.
  const auto patent = [](int replaced, const std::string& row, const std::string& extra = "") {
    return testing::hostilePatentTable(replaced, row, extra);
  };
  lens("patent-row-without-thickness.txt", patent(4, "2 -200"), "surface 2 has no d", "4:7");
  lens("patent-no-f-number.txt", patent(1, "f = 52.1  2ω 20"), "states no f-number", "5:1");
  lens("patent-asphere-of-no-surface.txt", patent(0, "", "Surface 9: K = 0 A4 = 1.0E-05\n"),
       "aspheric data for surface 9, which the table does not have", "10:1");
  lens("patent-one-row.txt", "Fno 2\nSurface r d nd vd\n1(Stop) 50 40 1.5168 64.2\n",
       "the film would be inside glass", "3:15");
  lens("patent-huge-exponent.txt", patent(9, "Surface 1: K = -0.5 A4 = 1.0E+400"),
       "aspheric coefficient 'a4' is out of range", "9:21");
  lens("patent-nan-radius.txt", patent(4, "2 nan 2"), "'nan' is not a number (r of surface 2)",
       "4:3");
  lens("patent-inf-index.txt", patent(3, "1* 50 5 inf 64.2"), "is not a refractive index", "3:9");
  lens("patent-inf-conic.txt", patent(9, "Surface 1: K = inf A4 = 1.0E-07"),
       "aspheric coefficient 'k' is infinite", "9:12");
  lens("patent-nan-f-number.txt", patent(1, "f = 52.1  Fno nan  2ω 20"), "Fno is not a number",
       "1:15");
  lens("empty.txt", "", "no surface table found", "1:1");
  lens("ten-megabyte-line.dat", std::string(10'000'000, 'x') + "\n" + lensText,
       "(10000000 characters)", "1:1");
  lens("three-million-numbers.dat", "29.475" + threeMillion + "\n" + lensText,
       "too many numbers in this row", "1:24");
  lens("ten-million-digits.dat", std::string(10'000'000, '7') + "\t3.76\t1.67\t25.2\n" + lensText,
       "(10000000 characters)", "1:1");
  // Ten thousand flat surfaces, 1 mm apart, glass and air by turns, the stop in the middle: a
  // lens no surface of which crosses another, refused for its size alone.
  std::string tenThousand;
  for (int i = 0; i < 10'000; ++i) {
    tenThousand += i == 5'000 ? "0\t1\t0\t10\n" : (i % 2 ? "inf\t1\t1\t20\n" : "inf\t1\t1.5\t20\n");
  }
  lens("ten-thousand-surfaces.dat", tenThousand, "too many surfaces", "257:1");

  // NaN and infinity in place of each number of a valid scene and of a valid lens.
  const std::string sweepScene = testing::readWholeFile(source / "sweep" / "every-number.pbrt");
  fs::copy_file(source / "sweep" / "every-number.pbrt", directory / "every-number.pbrt",
                fs::copy_options::overwrite_existing);
  int index = 0;
  for (const NumberToken& number : numberTokens(sweepScene)) {
    for (const char* value : {"nan", "inf", "-inf"}) {
      std::string text = sweepScene;
      text.replace(number.offset, number.length, value);
      scene("every-number-" + std::to_string(index++) + "-" + value + ".pbrt", text, "",
            std::to_string(number.line) + ":" + std::to_string(number.column));
    }
  }
  index = 0;
  for (const NumberToken& number : numberTokens(lensText)) {
    // The first number of a row is its radius, which may be inf: a flat surface.
    const bool radius = number.column == 1;
    for (const char* value : {"nan", "inf", "-inf"}) {
      if (radius && value[0] != 'n') continue;
      std::string text = lensText;
      text.replace(number.offset, number.length, value);
      lens("every-number-" + std::to_string(index++) + "-" + value + ".dat", text, "",
           std::to_string(number.line) + ":" + std::to_string(number.column));
    }
  }
  return cases;
}

}  // namespace lenslab::hostile
