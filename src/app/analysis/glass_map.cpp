#include "app/analysis/glass_map.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace lenslab::app {

std::uint32_t glassMakerColour(std::size_t makerIndex) {
  // Thirteen makers: distinct hues that read on the dark theme (and in print), the big six first.
  static constexpr std::uint32_t kColours[] = {
      0x4fc3f7ffu,  // light blue
      0xffb74dffu,  // orange
      0x81c784ffu,  // green
      0xe57373ffu,  // red
      0xba68c8ffu,  // purple
      0xfff176ffu,  // yellow
      0x4db6acffu,  // teal
      0xf06292ffu,  // pink
      0xa1887fffu,  // brown
      0x9fa8daffu,  // indigo
      0xdce775ffu,  // lime
      0xb0bec5ffu,  // grey
      0xff8a65ffu,  // deep orange
  };
  return kColours[makerIndex % (sizeof kColours / sizeof kColours[0])];
}

GlassMap::GlassMap(std::shared_ptr<const optics::GlassCatalog> catalog)
    : catalog_(std::move(catalog)) {
  if (!catalog_) return;
  makers_ = catalog_->makers();
  for (const optics::CatalogGlass& glass : catalog_->glasses()) {
    if (!glass.nd || !glass.vd) continue;
    const auto maker = std::find(makers_.begin(), makers_.end(), glass.maker);
    if (*glass.nd < kGlassMapNdBottom || *glass.nd > kGlassMapNdTop ||
        *glass.vd > kGlassMapVdLeft || *glass.vd < kGlassMapVdRight) {
      outside_.push_back(glass.name);
      continue;
    }
    points_.push_back(
        {&glass, *glass.vd, *glass.nd, static_cast<std::size_t>(maker - makers_.begin())});
  }
}

PlotSpec GlassMap::plot(const std::set<std::string>& hidden) const {
  PlotSpec spec;
  // Both numbers have no unit: the axes say what they are, at which lines.
  spec.x.label = "Abbe number V_d = (n_d - 1) / (n_F - n_C)";
  spec.y.label = "refractive index n_d (at 587.6 nm)";
  spec.x.min = kGlassMapVdRight;
  spec.x.max = kGlassMapVdLeft;
  spec.x.reversed = true;
  spec.y.min = kGlassMapNdBottom;
  spec.y.max = kGlassMapNdTop;
  spec.legend = false;  // the makers' check boxes, each in its colour, are the legend
  spec.readout = false;
  std::vector<PlotSeries> series(makers_.size());
  for (std::size_t m = 0; m < makers_.size(); ++m) {
    series[m].name = makers_[m];
    series[m].points = true;
    series[m].pointScale = 1.6f;
    series[m].rgba = glassMakerColour(m);
  }
  for (const Point& point : points_) {
    series[point.maker].x.push_back(point.vd);
    series[point.maker].y.push_back(point.nd);
  }
  for (std::size_t m = 0; m < makers_.size(); ++m) {
    if (hidden.count(makers_[m]) == 0 && !series[m].x.empty())
      spec.series.push_back(std::move(series[m]));
  }
  return spec;
}

std::size_t GlassMap::shownCount(const std::set<std::string>& hidden) const {
  return static_cast<std::size_t>(
      std::count_if(points_.begin(), points_.end(),
                    [&](const Point& p) { return hidden.count(makers_[p.maker]) == 0; }));
}

std::vector<LensGlassMark> lensGlassMarks(const optics::Prescription& lens) {
  std::vector<LensGlassMark> marks;
  for (std::size_t i = 0; i < lens.surfaces.size(); ++i) {
    const optics::Surface& surface = lens.surfaces[i];
    LensGlassMark mark;
    if (surface.glass) {
      if (!surface.glass->nd || !surface.glass->vd) continue;
      mark.label = surface.glass->name;
      mark.vd = *surface.glass->vd;
      mark.nd = *surface.glass->nd;
      mark.catalogue = true;
    } else {
      // Air, and a medium without dispersion, have no place on the map.
      if (surface.mediumIndexD() <= 1.0 || !surface.abbeD || !std::isfinite(*surface.abbeD) ||
          !std::isfinite(surface.indexD))
        continue;
      char text[48];
      std::snprintf(text, sizeof text, "model %.3f/%.1f", surface.indexD, *surface.abbeD);
      mark.label = text;
      mark.vd = *surface.abbeD;
      mark.nd = surface.indexD;
    }
    const auto same = std::find_if(marks.begin(), marks.end(), [&](const LensGlassMark& m) {
      return m.label == mark.label && m.nd == mark.nd && m.vd == mark.vd;
    });
    if (same != marks.end()) {
      same->surfaces.push_back(i + 1);
    } else {
      mark.surfaces.push_back(i + 1);
      marks.push_back(std::move(mark));
    }
  }
  return marks;
}

}  // namespace lenslab::app
