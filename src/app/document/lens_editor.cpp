#include "app/document/lens_editor.h"

namespace lenslab::app {

CommandTicket LensEditor::issue(EditCommand command, std::string mergeKey, CommandSource source) {
  const CommandTicket ticket = nextTicket_++;
  queue_.push_back({std::move(command), std::move(mergeKey), source, ticket});
  return ticket;
}

void LensEditor::endMerge() {
  if (queue_.empty()) {
    document_.endMerge();
  } else {
    queue_.back().endsMerge = true;
  }
}

std::vector<AppliedCommand> LensEditor::applyQueued() {
  std::vector<AppliedCommand> applied;
  applied.reserve(queue_.size());
  for (IssuedCommand& issued : queue_) {
    std::optional<std::string> refusal = document_.apply(issued.command, issued.mergeKey);
    if (issued.endsMerge) document_.endMerge();
    outcomes_.emplace_back(issued.ticket, refusal.value_or(""));
    if (outcomes_.size() > kKeptOutcomes) outcomes_.pop_front();
    applied.push_back({std::move(issued), std::move(refusal)});
  }
  queue_.clear();
  return applied;
}

std::optional<std::string> LensEditor::outcome(CommandTicket ticket) const {
  for (const auto& [kept, refusal] : outcomes_) {
    if (kept == ticket) return refusal;
  }
  return std::nullopt;
}

}  // namespace lenslab::app
