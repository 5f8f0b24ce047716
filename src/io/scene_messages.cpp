#include "scene_messages.h"

#include <algorithm>
#include <climits>
#include <cstdio>

namespace fosssim::io {

std::string withThousands(long n) {
  std::string digits = std::to_string(n < 0 ? -n : n), out;
  for (size_t k = 0; k < digits.size(); ++k) {
    if (k > 0 && (digits.size() - k) % 3 == 0) out += ',';
    out += digits[k];
  }
  return n < 0 ? "-" + out : out;
}

std::string shortNumber(double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%g", value);
  return buffer;
}

std::string SceneMessages::at(int line) const {
  return line > 0 ? file_ + ":" + std::to_string(line) + ": " : file_ + ": ";
}

void SceneMessages::warn(int line, const std::string& kind, const std::string& plural, const std::string& text) {
  ++warningCount_;
  Kind& k = kinds_[kind];
  if (k.count++ == 0) {
    k.plural = plural;
    k.order = arrivals_;
  }
  if (k.count > kShownPerKind || shownWarnings_ >= kShownWarnings) {
    if (k.hidden++ == 0) k.firstHiddenLine = line;
    k.lastHiddenLine = std::max(k.lastHiddenLine, line);
    return;
  }
  ++shownWarnings_;
  held_.push_back(Held{SceneMessage{SceneMessage::Severity::Warning, line, text}, arrivals_++});
}

void SceneMessages::error(int line, const std::string& text) {
  if (errorCount_++ >= kShownErrors) return;
  held_.push_back(Held{SceneMessage{SceneMessage::Severity::Error, line, text}, arrivals_++});
}

Status SceneMessages::finish(SceneFile& out) {
  // Line order; messages about the whole file (line 0) last; on one line warnings first (the
  // unknown attribute 'raduis' before the missing 'radius' it explains), then arrival order.
  auto key = [](const Held& h) {
    return std::make_tuple(h.message.line > 0 ? h.message.line : INT_MAX, h.message.isError(), h.order);
  };
  std::sort(held_.begin(), held_.end(), [&](const Held& a, const Held& b) { return key(a) < key(b); });
  out.messages.clear();
  for (Held& h : held_) out.messages.push_back(std::move(h.message));
  held_.clear();

  // Summaries of what was not shown, kinds in order of first appearance.
  std::vector<const Kind*> hidden;
  for (const auto& [name, kind] : kinds_)
    if (kind.hidden > 0) hidden.push_back(&kind);
  std::sort(hidden.begin(), hidden.end(), [](const Kind* a, const Kind* b) { return a->order < b->order; });
  constexpr size_t kSummaries = 10;
  long restCount = 0, restKinds = 0;
  for (size_t k = 0; k < hidden.size(); ++k) {
    const Kind& kind = *hidden[k];
    if (k >= kSummaries) {
      restCount += kind.hidden, ++restKinds;
      continue;
    }
    std::string lines =
        kind.firstHiddenLine <= 0 ? ""
        : kind.firstHiddenLine == kind.lastHiddenLine
            ? " (line " + withThousands(kind.firstHiddenLine) + ")"
            : " (lines " + withThousands(kind.firstHiddenLine) + "-" + withThousands(kind.lastHiddenLine) + ")";
    out.messages.push_back({SceneMessage::Severity::Warning, 0,
                            at(0) + "... and " + withThousands(kind.hidden) + " more " + kind.plural + lines});
  }
  if (restCount > 0)
    out.messages.push_back({SceneMessage::Severity::Warning, 0,
                            at(0) + "... and " + withThousands(restCount) + " more warnings of " +
                                withThousands(restKinds) + " other kinds"});
  if (errorCount_ > kShownErrors)
    out.messages.push_back({SceneMessage::Severity::Error, 0,
                            at(0) + "... and " + withThousands(errorCount_ - kShownErrors) + " more errors"});

  out.warnings.clear();
  for (const SceneMessage& m : out.messages)
    if (!m.isError()) out.warnings.push_back(m.text);
  out.warningCount = warningCount_;
  out.errorCount = errorCount_;
  if (errorCount_ == 0) return Status::ok();
  const auto first =
      std::find_if(out.messages.begin(), out.messages.end(), [](const SceneMessage& m) { return m.isError(); });
  std::string message = first->text;
  if (errorCount_ > 1) message += " (and " + withThousands(errorCount_ - 1) + " more errors)";
  return Status::error(message);
}

std::string clip(const std::string& text) {
  constexpr size_t kShown = 40;
  if (text.size() <= kShown) return text;
  return text.substr(0, kShown - 3) + "... (" + withThousands(static_cast<long>(text.size())) + " characters)";
}

}  // namespace fosssim::io
