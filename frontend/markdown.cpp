#include "markdown.hpp"

#include <algorithm>

#include "strings.hpp"

namespace fmbd::frontend::markdown {
namespace {

// The lines of `text` and whether it ended with a newline.
std::string join(const std::vector<std::string>& lines, bool final_newline) {
  std::string out;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    out += lines[i];
    if (i + 1 < lines.size() || final_newline) out += '\n';
  }
  return out;
}

bool ends_in_newline(std::string_view text) { return !text.empty() && text.back() == '\n'; }

// A relative target that is missing: its anchor aside, neither empty, absolute nor a URL.
bool lacks(std::string target, const std::function<bool(const std::string&)>& exists) {
  target = target.substr(0, target.find('#'));
  if (target.empty() || target[0] == '/') return false;
  const std::size_t colon = target.find(':');
  if (colon != std::string::npos && colon > 0 &&
      std::all_of(target.begin(), target.begin() + static_cast<std::ptrdiff_t>(colon),
                  [](char c) { return c >= 'a' && c <= 'z'; })) {
    return false;
  }
  return !exists(target);
}

}  // namespace

std::string strip_marked(std::string_view text, const std::vector<std::string>& marks) {
  std::vector<std::string> kept;
  bool skip = false;
  for (const std::string& line : tools::split_lines(text)) {
    for (const std::string& mark : marks) {
      if (line == "<!-- " + mark + " -->") skip = true;
    }
    if (!skip) kept.push_back(line);
    for (const std::string& mark : marks) {
      if (line == "<!-- /" + mark + " -->") skip = false;
    }
  }
  return join(kept, ends_in_newline(text));
}

std::string squeeze_blank_lines(std::string_view text) {
  std::vector<std::string> kept;
  for (const std::string& line : tools::split_lines(text)) {
    if (line.empty() && !kept.empty() && kept.back().empty()) continue;
    kept.push_back(line);
  }
  return join(kept, ends_in_newline(text));
}

std::string drop_missing_links(std::string_view text, const std::function<bool(const std::string&)>& exists) {
  std::vector<std::string> kept;
  for (const std::string& whole : tools::split_lines(text)) {
    std::string rest = whole;
    std::string line;
    bool drop = false;
    for (;;) {
      // The next "](target)" whose target holds neither ')' nor a space.
      std::size_t at = rest.find("](");
      std::size_t close = std::string::npos;
      while (at != std::string::npos) {
        close = rest.find_first_of(") ", at + 2);
        if (close != std::string::npos && rest[close] == ')' && close > at + 2) break;
        at = rest.find("](", at + 1);
      }
      if (at == std::string::npos) break;
      std::string head = rest.substr(0, at);
      const std::string link = rest.substr(at, close + 1 - at);
      rest = rest.substr(close + 1);
      if (!lacks(link.substr(2, link.size() - 3), exists)) {
        line += head + link;
        continue;
      }
      if (!whole.empty() && whole[0] == '|') {
        drop = true;
        break;
      }
      const std::size_t open = head.rfind('[');
      if (open != std::string::npos) {
        const bool image = open > 0 && head[open - 1] == '!';
        head = head.substr(0, image ? open - 1 : open) + head.substr(open + 1);
      }
      line += head;
    }
    if (!drop) kept.push_back(line + rest);
  }
  return join(kept, ends_in_newline(text));
}

}  // namespace fmbd::frontend::markdown
