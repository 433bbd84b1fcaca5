#pragma once
// The lens being edited. Every change is an explicit command (set the radius of surface 3 to
// 40 mm, flip the lens, undo, ...) applied to the prescription, recorded for undo and counted by
// a generation number that the viewer watches to rebuild the optics and restart the render. The
// viewer changes it only through LensEditor (lens_editor.h), which queues the commands of a frame
// and applies them in one place.

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "optics/design_conditions.h"
#include "optics/lens_file.h"
#include "optics/prescription.h"

namespace lenslab::app {

// What a lens file says of its lens besides the prescription (optics::LensFile): kept with the
// lens while it is edited, through undo and redo, and written back when it is saved, so that
// saving a .lens keeps its title, source, published focal length and design conditions.
struct LensDetails {
  std::vector<std::string> notes;  // the file's header comments (a .lens's `note` lines)
  std::string title;
  std::string source;                    // the publication the prescription comes from
  std::optional<double> publishedEflMm;  // the focal length printed there
  optics::DesignConditions design;       // design wavelengths, fields and aperture
  std::string lensType;                  // `double-Gauss`, `telephoto`, ...
  std::optional<int> year;               // of the source
  bool empty() const {
    return notes.empty() && title.empty() && source.empty() && !publishedEflMm && design.empty() &&
           lensType.empty() && !year;
  }
};
LensDetails detailsOf(const optics::LensFile& file);
// The file that saving writes: the prescription with the details.
optics::LensFile lensFileOf(const optics::Prescription& prescription, const LensDetails& details);

// Conic: the conic constant k of the surface's profile (optics/aspheric_profile.h; 0 a sphere).
enum class SurfaceField { RadiusMm, ThicknessMm, IndexD, AbbeD, ApertureDiameterMm, Conic };

// Parses "radius", "thickness", "n", "nd", "abbe", "vd", "aperture", "conic", "k"; nullopt
// otherwise.
std::optional<SurfaceField> surfaceFieldFromName(const std::string& name);
const char* surfaceFieldName(SurfaceField field);

struct SetSurfaceField {
  std::size_t surface;
  SurfaceField field;
  double value;  // for AbbeD, NaN clears it (non-dispersive)
};
// A_power r^power of the surface's profile, in mm^(1 - power). The stop has no shape to carry
// one, a power outside AsphericProfile's range has no term, and a non-finite value is no term
// either: the document refuses them (as it refuses a conic on the stop, or a non-finite one).
struct SetAsphericTerm {
  std::size_t surface;
  int power;
  double value;
};
// The medium after the surface becomes a catalogue glass, with its n_d and V_d (setCatalogGlass).
// The doors find the glass by name first (glass_choice.h), so that an unknown name is refused
// there with the nearest names; the document refuses the stop (a hole in air), no glass, and a
// glass with no index in the visible (an infrared material), keeping the lens as it was.
struct SetSurfaceGlass {
  std::size_t surface;
  std::shared_ptr<const optics::CatalogGlass> glass;
};
struct MakeStop {
  std::size_t surface;  // becomes the aperture stop (radius 0, air after it)
};
struct InsertSurface {
  std::size_t before;  // == size() appends
  optics::Surface surface;
};
struct DeleteSurface {
  std::size_t surface;
};
struct MoveSurface {
  std::size_t from, to;
};
struct FlipLens {};
struct ScaleLens {
  // every length (radii, thicknesses, apertures, film distance; the aspheric terms as lengths do)
  double factor;
};
struct SetFilmDistance {
  double mm;
};
struct SetStopDiameter {
  double mm;
};
// The stop's shape: circle, blades or an image mask (already loaded; optics/aperture_shape.h).
struct SetStopShape {
  optics::ApertureShape shape;
};
struct ReplaceLens {
  optics::Prescription prescription;
  std::string path;          // where it came from; empty for an unsaved lens
  LensDetails details = {};  // the file's, kept for saving
  // The lens the session starts with (the default or --lens, or the scene's): while nothing has
  // been edited it replaces the document without an undo step, so that there is nothing to undo
  // at the start. Once something has been edited it is an ordinary, undoable replacement.
  bool startsSession = false;
};
// Undo and redo are commands too, so that they take the same path as every other change.
struct Undo {};
struct Redo {};

using EditCommand =
    std::variant<SetSurfaceField, SetAsphericTerm, SetSurfaceGlass, MakeStop, InsertSurface,
                 DeleteSurface, MoveSurface, FlipLens, ScaleLens, SetFilmDistance, SetStopDiameter,
                 SetStopShape, ReplaceLens, Undo, Redo>;

// What a command does, in words, for the log and the Edit menu ("set radius of surface 3").
std::string describe(const EditCommand& command);

class LensDocument {
 public:
  LensDocument() = default;
  explicit LensDocument(optics::Prescription prescription, std::string path = {});

  const optics::Prescription& prescription() const { return current_; }
  const std::string& path() const { return path_; }
  // What the file the lens came from says of it (title, notes, ...), written back when it is
  // saved.
  const LensDetails& details() const { return details_; }
  // Bumped by every change, undo and redo included.
  std::uint64_t generation() const { return generation_; }

  // Applies a command. Commands that name a surface that does not exist (or would leave no
  // surface), and an undo or redo with nothing to undo or redo, are refused with a message and
  // change nothing. Values are not range-checked here:
  // an invalid lens is allowed while editing and flagged by validation.
  //
  // `mergeKey`: consecutive commands with the same non-empty key (a slider being dragged)
  // become one undo step.
  std::optional<std::string> apply(const EditCommand& command, const std::string& mergeKey = {});

  bool canUndo() const { return !undo_.empty(); }
  bool canRedo() const { return !redo_.empty(); }
  // What apply(Undo{}) and apply(Redo{}) do; false when there is nothing to undo or redo.
  bool undo();
  bool redo();
  // Ends the current merge group, so the next command starts a new undo step.
  void endMerge() { lastMergeKey_.clear(); }
  // The lens was saved to `path`: it becomes the lens's path and its unmodified state.
  void markSaved(std::string path);
  // The lens differs from what was last opened or saved (undoing back to it clears this).
  bool modified() const;

 private:
  struct Snapshot {
    optics::Prescription prescription;
    std::string path;
    LensDetails details;
    // What that lens was last opened or saved as: undoing back across opening another lens
    // compares the earlier lens with its own file, not with the one opened after it.
    optics::Prescription saved;
    // Which opened lens the step belongs to (openedLens_ then): saving renames and re-baselines
    // the steps of the lens saved, not those of a lens opened before it.
    std::uint64_t openedLens = 0;
  };
  Snapshot snapshot() const { return {current_, path_, details_, saved_, openedLens_}; }
  void restore(Snapshot&& from);
  // A step is two prescriptions, the lens and what its file holds (about a kilobyte each for a
  // 13-surface lens; an image stop's mask is shared, not copied): 5,000 steps hold an
  // afternoon's editing in about ten megabytes, and a thousand random edits can all be undone
  // (the edit-storm test).
  static constexpr std::size_t kMaxUndoSteps = 5000;

  optics::Prescription current_;
  std::string path_;
  LensDetails details_;
  optics::Prescription saved_;      // as last opened or saved
  std::uint64_t openedLens_ = 0;    // the lens the current state belongs to
  std::uint64_t lensesOpened_ = 0;  // ReplaceLens commands applied: each opens a new lens
  std::vector<Snapshot> undo_, redo_;
  std::string lastMergeKey_;
  std::uint64_t generation_ = 0;
};

// Pure transformations, also used by the commands.
optics::Prescription flipped(const optics::Prescription& lens);
optics::Prescription scaled(const optics::Prescription& lens, double factor);
// A surface's conic and polynomial terms seen from its other side (every A_i negated, k kept: the
// radius's sign flips with them), and magnified by `factor` (A_i * factor^(1 - i), k kept).
optics::AsphericProfile mirroredProfile(const optics::AsphericProfile& profile);
optics::AsphericProfile scaledProfile(const optics::AsphericProfile& profile, double factor);

}  // namespace lenslab::app
