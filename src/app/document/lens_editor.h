#pragma once
// The one way the viewer changes its lens. Every door (a table cell, a drag in the cross-section,
// the menus, Ctrl+Z, a script, a click on the preview to focus, opening a lens or a scene) issues
// an EditCommand here; applyQueued() applies the commands issued since the last call, in order,
// and the viewer calls it once per frame (applyCommands, viewer_state.h). Each applied command is
// recorded for undo and bumps the document's one generation counter, which the optics, the
// cross-section and the renderer key their results on. Nothing else can change the document:
// this class gives read-only access to it.

#include <cstdint>
#include <deque>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "app/document/lens_document.h"

namespace lenslab::app {

// Who issued a command: the log tells a script's edits from the user's.
enum class CommandSource { User, Script };

// Identifies an issued command until it has been applied, for those that wait for its outcome
// (a script's edit fails the script when the document refuses it).
using CommandTicket = std::uint64_t;

struct IssuedCommand {
  EditCommand command;
  // Consecutive commands with the same non-empty key (a drag, every frame) undo as one step.
  std::string mergeKey;
  CommandSource source = CommandSource::User;
  CommandTicket ticket = 0;
  bool endsMerge = false;  // the merge group ends after this command (endMerge)
};

// What applying an issued command did.
struct AppliedCommand {
  IssuedCommand issued;
  std::optional<std::string> refusal;  // why the document refused it; nullopt when applied
};

class LensEditor {
 public:
  LensEditor() = default;

  // The document as of the last applyQueued(): what every panel shows.
  const LensDocument& document() const { return document_; }
  const optics::Prescription& prescription() const { return document_.prescription(); }
  const std::string& path() const { return document_.path(); }
  std::uint64_t generation() const { return document_.generation(); }
  bool canUndo() const { return document_.canUndo(); }
  bool canRedo() const { return document_.canRedo(); }
  bool modified() const { return document_.modified(); }

  // Queues a command for the next applyQueued().
  CommandTicket issue(EditCommand command, std::string mergeKey = {},
                      CommandSource source = CommandSource::User);
  bool hasQueued() const { return !queue_.empty(); }
  // The ticket of the last command issued (0 before any): a caller that holds an earlier ticket
  // learns that something was issued after it.
  CommandTicket lastIssued() const { return nextTicket_ - 1; }
  // A drag was released: the next command starts a new undo step, even with the same merge key.
  // Takes effect in order, after the commands already queued.
  void endMerge();

  // The one place the document changes: applies the queued commands in the order issued and
  // returns what each did.
  std::vector<AppliedCommand> applyQueued();

  // nullopt while the command waits to be applied; then "" once applied, or why it was refused.
  // Outcomes are kept for the last kKeptOutcomes commands.
  std::optional<std::string> outcome(CommandTicket ticket) const;

  // The lens was saved to `path`: not an edit (nothing to undo, no new generation), but the
  // lens's path and what "modified" compares against.
  void markSaved(std::string path) { document_.markSaved(std::move(path)); }

 private:
  static constexpr std::size_t kKeptOutcomes = 256;

  LensDocument document_;
  std::vector<IssuedCommand> queue_;
  CommandTicket nextTicket_ = 1;
  std::deque<std::pair<CommandTicket, std::string>> outcomes_;  // oldest first
};

}  // namespace lenslab::app
