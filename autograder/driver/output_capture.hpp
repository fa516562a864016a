#pragma once
// The parent's side of a test process's output (sandbox.cpp): what is kept of it, and whether its
// completion token came (the protocol's line, common/grading_protocol.hpp).

#include <algorithm>
#include <cstddef>
#include <cstring>
#include <string>
#include <string_view>

#include "sandbox.hpp"

namespace fmbd::grade {

// Collects a process's output: keeps the first bytes, counts the rest, and checks every
// line of the whole stream for the completion token.
class OutputCapture {
 public:
  // A token line is short; longer lines are not examined (they are kept as output all the same).
  static constexpr std::size_t kMaxLine = 256;

  OutputCapture(const std::string& token, std::size_t max_kept)
      : expected_line_(kCompletionTokenPrefix + token), max_kept_(max_kept) {}

  void append(std::string_view data) {
    const std::size_t room = max_kept_ - std::min(max_kept_, kept_.size());
    kept_.append(data.substr(0, room));
    total_ += data.size();
    discarded_ += data.size() - std::min(room, data.size());
    while (!data.empty()) {
      const std::size_t newline = data.find('\n');
      add_to_line(data.substr(0, newline));
      if (newline == std::string_view::npos) break;
      end_line();
      data.remove_prefix(newline + 1);
    }
  }

  // Call once, at the end of the stream.
  std::string finish() {
    end_line();
    remove_matching_token_line();
    std::string output(trim_end(kept_));
    if (truncated()) {
      output += "\n[output truncated] (kept the first " + std::to_string(total_ - discarded_) +
                " of " + std::to_string(total_) + " bytes)";
    }
    return output;
  }

  bool truncated() const { return discarded_ > 0; }

  TokenSeen token_seen() const {
    if (saw_matching_) return TokenSeen::matching;
    return saw_other_ ? TokenSeen::wrong : TokenSeen::none;
  }

 private:
  static std::string_view trim_end(std::string_view text) {
    const std::size_t end = text.find_last_not_of(" \t\r\n");
    return text.substr(0, end == std::string_view::npos ? 0 : end + 1);
  }

  void add_to_line(std::string_view piece) {
    if (line_too_long_) return;
    if (line_.size() + piece.size() > kMaxLine) {
      line_too_long_ = true;
      line_.clear();
    } else {
      line_.append(piece);
    }
  }

  void end_line() {
    if (!line_too_long_) {
      if (!line_.empty() && line_.back() == '\r') line_.pop_back();
      if (line_ == expected_line_) {
        saw_matching_ = true;
      } else if (line_.compare(0, std::strlen(kCompletionTokenPrefix), kCompletionTokenPrefix) ==
                 0) {
        saw_other_ = true;
      }
    }
    line_.clear();
    line_too_long_ = false;
  }

  // The token is of no use to a reader of the report.
  void remove_matching_token_line() {
    for (std::size_t at = kept_.find(expected_line_); at != std::string::npos;
         at = kept_.find(expected_line_, at + 1)) {
      const std::size_t end = kept_.find('\n', at);
      const std::string_view line = std::string_view(kept_).substr(at, end - at);
      if ((at == 0 || kept_[at - 1] == '\n') && trim_end(line) == expected_line_) {
        kept_.erase(at, end == std::string::npos ? end : end + 1 - at);
        return;
      }
    }
  }

  std::string expected_line_;
  std::size_t max_kept_;
  std::string kept_;
  std::size_t total_ = 0;
  std::size_t discarded_ = 0;
  std::string line_;
  bool line_too_long_ = false;
  bool saw_matching_ = false;
  bool saw_other_ = false;
};

}  // namespace fmbd::grade
