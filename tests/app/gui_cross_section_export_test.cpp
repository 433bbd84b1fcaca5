// The cross-section export for slides (export-cross-section, File > Export cross-section...): the
// real viewer under Xvfb writes PNG and SVG files, and the tests read them back with their own
// parsers: the PNG's chunks, the SVG's elements, and the lens's geometry from its prescription.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <regex>
#include <set>
#include <string>
#include <tuple>
#include <vector>

#include "optics/lens_loader.h"
#include "optics/ray_fan.h"

#include "support/png_image.h"
#include "support/run_process.h"

namespace lenslab {
namespace {

const std::string kLens = std::string(LENSLAB_SOURCE_DIR) + "/lenses/dgauss-50mm.dat";
// The default scene's film (scenes/default.pbrt: "float diagonal" [43.27]).
constexpr double kFilmDiagonalMm = 43.27;

class CrossSectionExport : public ::testing::Test {
 protected:
  // Runs the viewer on the double-Gauss 50 mm (kept over the default scene's lens).
  testing::ProcessResult runScript(const std::string& script) {
    const auto path = scratch / "commands.script";
    std::ofstream(path) << script;
    return testing::runProcess("cd '" + scratch.string() + "' && '" + LENSLAB_BINARY +
                                   "' --size 1000x700 --lens '" + kLens + "' --script '" +
                                   path.string() + "'",
                               scratch);
  }
  std::string file(const std::string& name) { return testing::readWholeFile(scratch / name); }
  std::filesystem::path scratch = testing::makeTestDirectory("export");
};

std::uint32_t bigEndian(const std::string& bytes, std::size_t at) {
  std::uint32_t value = 0;
  for (std::size_t i = 0; i < 4; ++i)
    value = (value << 8) | static_cast<std::uint8_t>(bytes[at + i]);
  return value;
}

// CRC-32 as PNG defines it, bit by bit (the writer uses a table).
std::uint32_t crcBitwise(const std::string& bytes) {
  std::uint32_t crc = 0xFFFFFFFFu;
  for (char c : bytes) {
    crc ^= static_cast<std::uint8_t>(c);
    for (int k = 0; k < 8; ++k) crc = (crc >> 1) ^ (0xEDB88320u & (0u - (crc & 1u)));
  }
  return ~crc;
}

struct PngChunk {
  std::string type, data;
  bool crcOk = false;
};

std::vector<PngChunk> pngChunks(const std::string& png) {
  std::vector<PngChunk> chunks;
  if (png.size() < 8 || png.compare(0, 8, "\x89PNG\r\n\x1a\n") != 0) return chunks;
  for (std::size_t at = 8; at + 12 <= png.size();) {
    const std::uint32_t length = bigEndian(png, at);
    if (at + 12 + length > png.size()) break;
    PngChunk chunk{png.substr(at + 4, 4), png.substr(at + 8, length)};
    chunk.crcOk = crcBitwise(png.substr(at + 4, 4 + length)) == bigEndian(png, at + 8 + length);
    chunks.push_back(chunk);
    at += 12 + length;
  }
  return chunks;
}

// The SVG's text elements by class, in order.
std::multimap<std::string, std::string> svgTexts(const std::string& svg) {
  std::multimap<std::string, std::string> texts;
  static const std::regex kText("<text class=\"([^\"]*)\"[^>]*>([^<]*)</text>");
  for (auto it = std::sregex_iterator(svg.begin(), svg.end(), kText); it != std::sregex_iterator();
       ++it) {
    texts.emplace((*it)[1].str(), (*it)[2].str());
  }
  return texts;
}

std::vector<std::string> textsOf(const std::multimap<std::string, std::string>& texts,
                                 const std::string& kind) {
  std::vector<std::string> found;
  for (auto [it, end] = texts.equal_range(kind); it != end; ++it) found.push_back(it->second);
  return found;
}

struct Point {
  double x = 0, y = 0;
};

// The points of every polyline of a class.
std::vector<std::vector<Point>> svgPolylines(const std::string& svg, const std::string& kind) {
  std::vector<std::vector<Point>> lines;
  const std::regex polyline("<polyline class=\"" + kind + "\"[^>]* points=\"([^\"]*)\"");
  for (auto it = std::sregex_iterator(svg.begin(), svg.end(), polyline);
       it != std::sregex_iterator(); ++it) {
    std::vector<Point> points;
    std::string list = (*it)[1].str();
    std::replace(list.begin(), list.end(), ',', ' ');
    std::istringstream numbers(list);
    Point point;
    while (numbers >> point.x >> point.y) points.push_back(point);
    lines.push_back(points);
  }
  return lines;
}

// The drawing's scale and the film's place, measured in the SVG: the film line is at z = 0, the
// stop's bars at the stop's z, which the prescription gives (the thicknesses from the stop to
// the film).
struct MeasuredScale {
  double pixelsPerMm = 0, filmX = 0, axisY = 0, filmLengthPx = 0;
};

MeasuredScale measureScale(const std::string& svg, const optics::Prescription& lens) {
  MeasuredScale scale;
  const auto film = svgPolylines(svg, "film");
  const auto stop = svgPolylines(svg, "stop");
  if (film.size() != 1 || film[0].size() != 2 || stop.empty()) return scale;
  scale.filmX = film[0][0].x;
  scale.axisY = 0.5 * (film[0][0].y + film[0][1].y);
  scale.filmLengthPx = std::abs(film[0][1].y - film[0][0].y);
  double stopZMm = 0;
  bool afterStop = false;
  for (const optics::Surface& surface : lens.surfaces) {
    afterStop |= surface.isStop();
    if (afterStop) stopZMm += surface.thicknessMm;
  }
  scale.pixelsPerMm = (scale.filmX - stop[0][0].x) / stopZMm;
  return scale;
}

TEST_F(CrossSectionExport, APngHasTheChosenSizeAndItsDpiInAPhysChunk) {
  const auto result = runScript(
      "wait-frames 2\nexport-cross-section slide.png 1600x900 300\ndump-ui ui.json\nquit\n");
  ASSERT_EQ(result.exitCode, 0) << result.err;
  const std::vector<PngChunk> chunks = pngChunks(file("slide.png"));
  ASSERT_GE(chunks.size(), 3u);
  ASSERT_EQ(chunks[0].type, "IHDR");
  EXPECT_EQ(bigEndian(chunks[0].data, 0), 1600u);
  EXPECT_EQ(bigEndian(chunks[0].data, 4), 900u);
  const auto phys = std::find_if(chunks.begin(), chunks.end(),
                                 [](const PngChunk& chunk) { return chunk.type == "pHYs"; });
  ASSERT_NE(phys, chunks.end());
  ASSERT_EQ(phys->data.size(), 9u);
  EXPECT_TRUE(phys->crcOk);
  EXPECT_EQ(phys->data[8], 1) << "the unit must be the metre";
  // 300 dots per inch, 0.0254 m to the inch: 11811 pixels per metre.
  for (std::size_t axis : {0u, 4u}) {
    EXPECT_NEAR(bigEndian(phys->data, axis) * 0.0254, 300.0, 0.01);
  }
  // Before the image data, as PNG requires.
  const auto data = std::find_if(chunks.begin(), chunks.end(),
                                 [](const PngChunk& chunk) { return chunk.type == "IDAT"; });
  EXPECT_LT(phys - chunks.begin(), data - chunks.begin());
  for (const PngChunk& chunk : chunks) EXPECT_TRUE(chunk.crcOk) << chunk.type;
  // A log line says where and what size.
  std::ifstream dumpFile(scratch / "ui.json");
  const nlohmann::json dump = nlohmann::json::parse(dumpFile, nullptr, false);
  std::string log;
  for (const auto& entry : dump["state"]["log"]) log += entry["text"].get<std::string>() + "\n";
  EXPECT_NE(log.find("Exported cross-section to slide.png (PNG, 1600×900 px, 300 DPI, light"),
            std::string::npos)
      << log;
}

TEST_F(CrossSectionExport, TheLightThemeIsWhiteWithGlassAndOutlinesWhereTheLensIs) {
  // The same picture as PNG and SVG: the SVG says where the film and stop are, the prescription
  // where the second element is from them, and the PNG must show glass there.
  const auto result = runScript(
      "wait-frames 2\nexport-cross-section slide.png 1600x900 light\n"
      "export-cross-section slide.svg 1600x900 light\nquit\n");
  ASSERT_EQ(result.exitCode, 0) << result.err;
  const auto image = testing::PngImage::load(scratch / "slide.png");
  ASSERT_TRUE(image.valid());
  ASSERT_EQ(image.width, 1600);
  const testing::Rgb white{255, 255, 255};
  for (const auto& [x, y] : {std::pair{2, 2}, {1597, 2}, {2, 897}, {1597, 897}, {800, 2}}) {
    EXPECT_EQ(image.at(x, y).maxDifference(white), 0) << x << "," << y;
  }
  const optics::Prescription lens = optics::loadLens(kLens).file.prescription;
  const MeasuredScale scale = measureScale(file("slide.svg"), lens);
  ASSERT_GT(scale.pixelsPerMm, 1.0);
  // The second element lies between surfaces 3 and 4; at 60% of its semi-aperture its front and
  // rear surfaces are where the spherical sags put them.
  const auto sag = [](double radius, double height) {
    return radius - std::copysign(std::sqrt(radius * radius - height * height), radius);
  };
  double vertex3 = 0;  // z of surface 3's vertex: the thicknesses from it to the film
  for (std::size_t i = 2; i < lens.surfaces.size(); ++i) vertex3 += lens.surfaces[i].thicknessMm;
  const double vertex4 = vertex3 - lens.surfaces[2].thicknessMm;
  const double heightMm = 0.6 * 0.5 * lens.surfaces[3].apertureDiameterMm;
  const double frontZ = vertex3 - sag(lens.surfaces[2].radiusMm, heightMm);
  const double rearZ = vertex4 - sag(lens.surfaces[3].radiusMm, heightMm);
  const auto toX = [&](double z) { return scale.filmX - z * scale.pixelsPerMm; };
  const int y = static_cast<int>(std::lround(scale.axisY - heightMm * scale.pixelsPerMm));
  // Light-blue glass (bluer than it is red, not white) fills most of the element's middle.
  int glass = 0, total = 0;
  const int middle = static_cast<int>(std::lround(toX(0.5 * (frontZ + rearZ))));
  for (int dy = -4; dy <= 4; ++dy) {
    for (int dx = -4; dx <= 4; ++dx) {
      const testing::Rgb pixel = image.at(middle + dx, y + dy);
      ++total;
      glass += pixel.b > pixel.r + 25 && pixel.b > 200 && pixel.maxDifference(white) > 20;
    }
  }
  EXPECT_GT(glass, total * 2 / 3) << "at " << middle << "," << y;
  // A dark outline at each of the element's surfaces.
  for (double z : {frontZ, rearZ}) {
    const int x = static_cast<int>(std::lround(toX(z)));
    int darkest = 255;
    for (int dx = -3; dx <= 3; ++dx) {
      const testing::Rgb pixel = image.at(x + dx, y);
      darkest = std::min(darkest, (pixel.r + pixel.g + pixel.b) / 3);
    }
    EXPECT_LT(darkest, 110) << "no outline near x = " << x;
  }
}

TEST_F(CrossSectionExport, TheSvgLabelsSurfacesStopFilmFieldsAndTheFNumber) {
  // The lens as the viewer shows it (opened over the scene, it is focused at the scene's
  // distance), saved for the fans traced here.
  const auto result = runScript(
      "wait-frames 2\nexport-cross-section slide.svg\nsave-lens shown.dat\n"
      "wait-frames 3\ndump-ui ui.json\nquit\n");
  ASSERT_EQ(result.exitCode, 0) << result.err;
  const std::string svg = file("slide.svg");
  EXPECT_NE(svg.find("width=\"1920\" height=\"1080\""), std::string::npos);
  const auto texts = svgTexts(svg);
  const optics::LoadedLens loaded = optics::loadLens(scratch / "shown.dat");
  ASSERT_TRUE(loaded.ok());
  std::set<std::string> expectedNumbers, numbers;
  for (std::size_t i = 1; i <= loaded.file.prescription.surfaces.size(); ++i) {
    expectedNumbers.insert(std::to_string(i));
  }
  for (const std::string& number : textsOf(texts, "surface-number")) numbers.insert(number);
  EXPECT_EQ(numbers, expectedNumbers);
  EXPECT_EQ(textsOf(texts, "stop-label"), std::vector<std::string>{"Stop"});
  EXPECT_EQ(textsOf(texts, "film-label"), std::vector<std::string>{"Film"});
  // The fields' angles: the fans traced here for the same lens and film.
  optics::FanSpec spec;
  spec.filmHalfDiagonalMm = 0.5 * kFilmDiagonalMm;
  const optics::RayFans fans = optics::computeRayFans(*loaded.system, spec);
  std::vector<std::string> angles;
  for (const optics::RayFan& fan : fans.fans) {
    char text[32];
    if (std::abs(fan.fieldAngleDeg) < 0.05) {
      std::snprintf(text, sizeof text, "0°");
    } else {
      std::snprintf(text, sizeof text, "%.1f°", fan.fieldAngleDeg);
    }
    angles.push_back(text);
  }
  ASSERT_EQ(angles.size(), 3u);
  EXPECT_EQ(textsOf(texts, "legend-field"), angles);
  // The f-number as the first-order section writes it (dump-ui), which is `lenslab info`'s
  // rounded to two decimals.
  // Built in steps: GCC 12 warns (-Wrestrict, a false positive) on the one-expression form.
  std::string infoCommand = "'";
  infoCommand += LENSLAB_BINARY;
  infoCommand += "' info '";
  infoCommand += kLens;
  infoCommand += "'";
  const auto info = testing::runProcess(infoCommand, scratch);
  std::smatch match;
  ASSERT_TRUE(std::regex_search(info.out, match, std::regex("f-number \\(infinity\\) +([0-9.]+)")))
      << info.out;
  std::ifstream dumpFile(scratch / "ui.json");
  const nlohmann::json dump = nlohmann::json::parse(dumpFile, nullptr, false);
  const std::string fNumber = dump["state"]["first_order"]["f_number"];
  char rounded[32];
  std::snprintf(rounded, sizeof rounded, "f/%.2f", std::stod(match[1].str()));
  EXPECT_EQ(fNumber, rounded);
  const auto subtitle = textsOf(texts, "subtitle");
  ASSERT_EQ(subtitle.size(), 1u);
  EXPECT_NE(subtitle[0].find("  " + fNumber + "  "), std::string::npos) << subtitle[0];
  EXPECT_NE(subtitle[0].find("object at infinity"), std::string::npos) << subtitle[0];
  // The name: the file's first header comment, without its nominal "f/2" (issue 38: the slide
  // said "f/2" in its title and the lens's real f-number beside it). One f-number on the slide.
  EXPECT_EQ(textsOf(texts, "title"),
            std::vector<std::string>{"Double-Gauss 50 mm, 22 degree half field"});
}

// An "rgb(r,g,b)" attribute's colour.
testing::Rgb rgbOf(const std::string& text) {
  std::smatch m;
  if (!std::regex_search(text, m, std::regex("rgb\\((\\d+),(\\d+),(\\d+)\\)"))) return {};
  return {std::stoi(m[1]), std::stoi(m[2]), std::stoi(m[3])};
}

// The SVG's text elements of a class with their fill colours, in order.
std::vector<std::pair<std::string, testing::Rgb>> svgColouredTexts(const std::string& svg,
                                                                   const std::string& kind) {
  std::vector<std::pair<std::string, testing::Rgb>> texts;
  const std::regex text("<text class=\"" + kind + "\"[^>]* fill=\"([^\"]*)\">([^<]*)</text>");
  for (auto it = std::sregex_iterator(svg.begin(), svg.end(), text); it != std::sregex_iterator();
       ++it) {
    texts.push_back({(*it)[2].str(), rgbOf((*it)[1].str())});
  }
  return texts;
}

TEST_F(CrossSectionExport, AFilmPointsBundleIsColouredByTheRimThatStopsItWithItsShares) {
  // Issue 38: with a film point chosen, the slide drew the bundle all in the first field's green
  // under the fans' legend. It must show what the panel shows: each stopped ray in its rim's
  // colour, the passing rays in the bundle's, and the shares that dump-ui reports.
  const auto result = runScript(
      "wait-frames 2\nset film-point 18\nwait-frames 2\n"
      "export-cross-section bundle.svg 1600x900 light\n"
      "export-cross-section bundle.png 1600x900 light\ndump-ui ui.json\nquit\n");
  ASSERT_EQ(result.exitCode, 0) << result.err;
  std::ifstream dumpFile(scratch / "ui.json");
  const nlohmann::json dump = nlohmann::json::parse(dumpFile, nullptr, false);
  const nlohmann::json& point = dump["state"]["film_point"];
  ASSERT_TRUE(point.is_object()) << dump["state"].dump().substr(0, 2000);
  std::vector<std::string> expected;
  char text[96];
  std::snprintf(text, sizeof text, "reaches it %.0f%%", 100.0 * point["passing"].get<double>());
  expected.push_back(text);
  for (const auto& share : point["blocked"]) {
    std::snprintf(text, sizeof text, "surface %d", share["surface"].get<int>());
    expected.push_back(text);
  }
  ASSERT_GE(expected.size(), 3u) << "the point must be vignetted by at least two rims";
  const std::string svg = file("bundle.svg");
  const auto shares = svgColouredTexts(svg, "legend-share");
  ASSERT_EQ(shares.size(), expected.size())
      << svg.substr(svg.size() > 6000 ? svg.size() - 6000 : 0);
  EXPECT_EQ(shares[0].first, expected[0]);
  for (std::size_t i = 1; i < shares.size(); ++i) {
    // "surface 3: 20%" or "surface 1 (front): 5%": the surface, then its share.
    EXPECT_EQ(shares[i].first.rfind(expected[i], 0), 0u) << shares[i].first;
    std::snprintf(text, sizeof text, ": %.0f%%",
                  100.0 * point["blocked"][i - 1]["fraction"].get<double>());
    EXPECT_NE(shares[i].first.find(text), std::string::npos) << shares[i].first;
  }
  // The fans' legend is gone: no field angles, no marginal ray.
  const auto texts = svgTexts(svg);
  EXPECT_TRUE(textsOf(texts, "legend-field").empty());
  const auto legend = textsOf(texts, "legend");
  EXPECT_EQ(std::find(legend.begin(), legend.end(), "marginal ray"), legend.end());
  EXPECT_NE(textsOf(texts, "subtitle").at(0).find("film point 18.0 mm"), std::string::npos);
  // Each share's colour is a colour of the rays, and the colours differ from one another.
  std::set<std::tuple<int, int, int>> rayColours, shareColours;
  const std::regex rayStroke("<polyline class=\"rays\"[^>]* stroke=\"([^\"]*)\"");
  for (auto it = std::sregex_iterator(svg.begin(), svg.end(), rayStroke);
       it != std::sregex_iterator(); ++it) {
    const testing::Rgb c = rgbOf((*it)[1].str());
    rayColours.insert({c.r, c.g, c.b});
  }
  for (const auto& [words, c] : shares) shareColours.insert({c.r, c.g, c.b});
  // No two shares in one colour (with eight colours cycled, surfaces 1 and 9 were both red).
  EXPECT_EQ(shareColours.size(), shares.size());
  for (const auto& [r, g, b] : shareColours) {
    EXPECT_EQ(rayColours.count({r, g, b}), 1u) << "rgb(" << r << "," << g << "," << b << ")";
  }
  // The PNG draws the rays in those colours: pixels of every stopping rim's colour in the
  // drawing (above the legend's band), not only its swatch.
  const auto image = testing::PngImage::load(scratch / "bundle.png");
  ASSERT_TRUE(image.valid());
  for (std::size_t i = 0; i < shares.size(); ++i) {
    const double inDrawing = image.fractionNear(0, 150, image.width, 700, shares[i].second, 12);
    EXPECT_GT(inDrawing * image.width * 550, 40.0) << shares[i].first;
  }
}

TEST_F(CrossSectionExport, TheScaleBarIsAsLongAsItsLabelSays) {
  for (const std::string size : {"1920x1080", "1024x768", "800x1200"}) {
    const auto result =
        runScript("wait-frames 2\nexport-cross-section slide.svg " + size + "\nquit\n");
    ASSERT_EQ(result.exitCode, 0) << result.err;
    const std::string svg = file("slide.svg");
    const MeasuredScale scale = measureScale(svg, optics::loadLens(kLens).file.prescription);
    ASSERT_GT(scale.pixelsPerMm, 1.0) << size;
    // The measured scale also gives the film its diagonal's length.
    EXPECT_NEAR(scale.filmLengthPx / scale.pixelsPerMm, kFilmDiagonalMm, 0.01 * kFilmDiagonalMm);
    const auto labels = textsOf(svgTexts(svg), "scale-bar-label");
    ASSERT_EQ(labels.size(), 1u) << size;
    std::smatch match;
    ASSERT_TRUE(std::regex_match(labels[0], match, std::regex("([0-9.]+) mm"))) << labels[0];
    const double labelMm = std::stod(match[1].str());
    // A round length: 1, 2 or 5 times a power of ten.
    const double mantissa = labelMm / std::pow(10.0, std::floor(std::log10(labelMm) + 1e-9));
    EXPECT_TRUE(std::abs(mantissa - 1) < 1e-6 || std::abs(mantissa - 2) < 1e-6 ||
                std::abs(mantissa - 5) < 1e-6)
        << labels[0];
    double barPx = 0;
    for (const auto& line : svgPolylines(svg, "scale-bar")) {
      if (line.size() == 2 && line[0].y == line[1].y) barPx = std::abs(line[1].x - line[0].x);
    }
    EXPECT_NEAR(barPx / scale.pixelsPerMm, labelMm, 0.005 * labelMm) << size;
  }
}

TEST_F(CrossSectionExport, TheFileBrowserExportsWithTheDialogsSettings) {
  // File > Export cross-section...: the dialog, then the browser; the picture is the export's
  // (1920x1080, light), drawn off screen, so neither the dialog nor the browser is in it.
  const auto result = runScript(
      "wait-frames 2\nopen-dialog export-cross-section\nwait-frames 2\ndump-ui dialog.json\n"
      "open-dialog save-cross-section\nwait-frames 2\ndialog-choose via-browser.png\n"
      "wait-until-file via-browser.png\nquit\n");
  ASSERT_EQ(result.exitCode, 0) << result.err;
  std::ifstream dumpFile(scratch / "dialog.json");
  const nlohmann::json dialog = nlohmann::json::parse(dumpFile, nullptr, false);
  EXPECT_TRUE(dialog["widgets"].contains("export-cross-section")) << dialog["widgets"];
  const auto image = testing::PngImage::load(scratch / "via-browser.png");
  ASSERT_TRUE(image.valid());
  EXPECT_EQ(image.width, 1920);
  EXPECT_EQ(image.height, 1080);
  // Mostly white: no dark dialog or browser over it.
  EXPECT_GT(image.fractionNear(0, 0, image.width, image.height, {255, 255, 255}, 0), 0.6);
}

TEST_F(CrossSectionExport, BadArgumentsAndPathsAreErrorsThatSayWhere) {
  auto result = runScript("export-cross-section slide.jpg\n");
  EXPECT_EQ(result.exitCode, 2);  // a script that does not parse is a usage error
  EXPECT_NE(
      result.err.find("commands.script:1:22: error: 'slide.jpg' does not end in .png or .svg"),
      std::string::npos)
      << result.err;
  result = runScript("wait-frames 1\nexport-cross-section /no/such/dir/slide.png\n");
  EXPECT_EQ(result.exitCode, 1);
  EXPECT_NE(result.err.find("/no/such/dir/slide.png"), std::string::npos) << result.err;
  result = runScript("wait-frames 1\nexport-cross-section slide.png 20000x100\n");
  EXPECT_EQ(result.exitCode, 1);
  EXPECT_NE(result.err.find("is not between 16 and 10000 pixels a side"), std::string::npos)
      << result.err;
}

}  // namespace
}  // namespace lenslab
