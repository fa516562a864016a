#pragma once
// The README filters of a student release: a release's READMEs and guides (docs/*.md) are true
// of the release. Each function takes a README's text and returns the filtered text.

#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace fmbd::frontend::markdown {

// `text` without the parts between a line "<!-- MARK -->" and a line "<!-- /MARK -->" (both lines
// left out too) for each MARK of `marks`; the lines must be exactly that.
std::string strip_marked(std::string_view text, const std::vector<std::string>& marks);

// `text` with every run of empty lines squeezed to one (cat -s).
std::string squeeze_blank_lines(std::string_view text);

// `text` without its links to what does not exist: for a link [text](target) whose relative
// target (its #anchor aside) `exists` says is missing, a table row ("|" first) is left out whole,
// elsewhere the link keeps its text ("[", "](target)" and an image's "!" go). Targets that are
// absolute, empty (an anchor) or a URL ("https:", "mailto:") are kept as they are.
std::string drop_missing_links(std::string_view text, const std::function<bool(const std::string&)>& exists);

}  // namespace fmbd::frontend::markdown
