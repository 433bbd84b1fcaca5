#pragma once
// How the exports (cross-section slides, saved plots) name the lens: by its name (the file's
// title; for a pbrt .dat, which has none, its first header comment; else the file's name) and its
// f-number written as the first-order section and dump-ui's `f_number` write it. A name that
// carries the designer's nominal f-number
// ("Double-Gauss 50 mm f/2, 22 degree half field") loses it, so that a slide never says "f/2" in
// its title and "f/2.48" beside it.

#include <string>

#include "app/document/lens_document.h"

namespace lenslab::app {

struct ViewerState;

// What the lens's file says of it (LensDetails): the document's, or, when it has none (a scene's
// lens), read from the lens's file.
LensDetails lensDetails(const ViewerState& state);

// `name` without its f-numbers (" f/2", ", f/1.35"): "Double-Gauss 50 mm, 22 degree half field".
std::string withoutNominalFNumber(const std::string& name);

// The lens's name, without its nominal f-number; "Untitled lens" when it has neither a title (or a
// .dat's header comment) nor a file.
std::string lensName(const ViewerState& state);
// The same for a file's details and path (the library browser names its lenses so).
std::string lensNameOf(const LensDetails& details, const std::string& path);
// The publication the lens comes from, as its file gives it; "" when it gives none.
std::string lensSource(const ViewerState& state);

// "f/2.48" (lens_figures.h's fNumberText), "afocal", or "" without a lens.
std::string lensFNumberText(const ViewerState& state);

// The name and the f-number: "Double-Gauss 50 mm, 22 degree half field · f/2.48".
std::string lensTitle(const ViewerState& state);

}  // namespace lenslab::app
