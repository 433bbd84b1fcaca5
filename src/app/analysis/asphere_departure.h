#pragma once
// How aspheric a surface is, as a student reads it off a plot: the sag of the surface minus the
// sag of its base sphere (the sphere of the same vertex radius), from the axis to the rim of its
// clear aperture. A conic or polynomial terms show as a curve leaving zero; a sphere is the zero
// line. Drawn by the lens table's asphere editor (dialogs/asphere_editor.cpp).

#include <cstddef>

#include "app/plot/plot_spec.h"
#include "optics/prescription.h"

namespace lenslab::app {

// The departure in mm at `heightMm`: S(r) - S_sphere(r) (aspheric_profile.h's sag, positive toward
// the centre of curvature). NaN where either sag has no real value (a conic past its real heights,
// a sphere past its radius), so that the plot leaves a gap there rather than a wrong number.
double asphereDepartureMm(const optics::Surface& surface, double heightMm);

// The plot of it against height, 0 to the semi-aperture in `samples` steps. Its y axis is in um
// while the departure stays under 0.1 mm (a typical molded asphere's), in mm beyond, and says
// which; `surfaceNumber` (from 1) names the surface in the title.
PlotSpec asphereDeparturePlot(const optics::Surface& surface, std::size_t surfaceNumber,
                              int samples = 121);

}  // namespace lenslab::app
