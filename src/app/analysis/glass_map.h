#pragma once
// The glass map (Lens > Glass map...): the classic Abbe diagram of the bundled catalogues, n_d up
// and V_d falling to the right, one colour per maker, the lens's own media marked. What it plots
// and which glass is under the mouse, without ImGui (dialogs/glass_map_window.cpp draws it with
// the one plot component, plot/plot_widget.h).

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "app/plot/plot_spec.h"
#include "optics/glass/glass_catalog.h"
#include "optics/prescription.h"

namespace lenslab::app {

// The axes every glass map here is drawn on, fixed so that hiding a maker moves no point: the
// optical glasses, the fluorides and the plastics (V_d 17 to 106, n_d 1.38 to 2.15). Diamond
// (n_d 2.42) is beyond the top; the map says which glasses it leaves out.
inline constexpr double kGlassMapVdLeft = 110.0, kGlassMapVdRight = 15.0;
inline constexpr double kGlassMapNdBottom = 1.35, kGlassMapNdTop = 2.20;

// What the map's window keeps between frames.
struct GlassMapState {
  bool open = false;
  std::set<std::string> hiddenMakers;  // unchecked in its filter
  // Drawn last frame (for dump-ui and the tests): the points shown, and the glass under the mouse.
  std::size_t pointsShown = 0;
  std::string hovered;  // "N-BK7 SCHOTT", or empty
  std::string message;  // the last click's outcome ("surface 3: N-BK7 (SCHOTT)", or why not)
};

// A maker's colour on the map (0xRRGGBBAA), by its place among the catalogue's makers.
std::uint32_t glassMakerColour(std::size_t makerIndex);

class GlassMap {
 public:
  // Every glass with an n_d and V_d (infrared materials have none: they cannot be placed).
  explicit GlassMap(std::shared_ptr<const optics::GlassCatalog> catalog);

  const std::vector<std::string>& makers() const { return makers_; }
  struct Point {
    const optics::CatalogGlass* glass = nullptr;
    double vd = 0.0, nd = 0.0;
    std::size_t maker = 0;  // index into makers()
  };
  const std::vector<Point>& points() const { return points_; }
  const std::shared_ptr<const optics::GlassCatalog>& catalog() const { return catalog_; }
  // The glasses outside the fixed axes ("diamond"), for the map's note.
  const std::vector<std::string>& outside() const { return outside_; }

  // The plot: one points series per maker not in `hidden`, on the fixed, V_d-reversed axes.
  PlotSpec plot(const std::set<std::string>& hidden) const;
  // How many points that plot draws.
  std::size_t shownCount(const std::set<std::string>& hidden) const;

  // The shown point nearest the screen position (px, py) within `radiusPx`, through the plot's
  // mapping `toScreen` (value -> pixel), or none. A scan of every point: 1,702 distances, a few
  // microseconds, against the frame's milliseconds (measured: see docs/viewer.md).
  template <class ToScreen>
  std::optional<std::size_t> nearest(float px, float py, float radiusPx,
                                     const std::set<std::string>& hidden,
                                     const ToScreen& toScreen) const {
    std::optional<std::size_t> best;
    float bestDistance = radiusPx * radiusPx;
    for (std::size_t i = 0; i < points_.size(); ++i) {
      if (hidden.count(makers_[points_[i].maker]) != 0) continue;
      const auto [x, y] = toScreen(points_[i].vd, points_[i].nd);
      const float distance = (x - px) * (x - px) + (y - py) * (y - py);
      if (distance <= bestDistance) {
        bestDistance = distance;
        best = i;
      }
    }
    return best;
  }

 private:
  std::shared_ptr<const optics::GlassCatalog> catalog_;
  std::vector<std::string> makers_;
  std::vector<Point> points_;
  std::vector<std::string> outside_;
};

// The lens's media on the map: each distinct glass once, with the surfaces it follows (1-based).
struct LensGlassMark {
  std::string label;  // "N-BK7" for a catalogue glass, "model 1.517/64.2" for a model glass
  double vd = 0.0, nd = 0.0;
  bool catalogue = false;
  std::vector<std::size_t> surfaces;
};
std::vector<LensGlassMark> lensGlassMarks(const optics::Prescription& lens);

}  // namespace lenslab::app
