#include "common/xml_nesting.hpp"

#include <algorithm>
#include <vector>

namespace common {

namespace {

/// A cursor over the text that keeps the line number.
class Cursor {
 public:
  explicit Cursor(std::string_view text) : text_(text) {}
  bool done() const { return at_ >= text_.size(); }
  bool startsWith(std::string_view s) const { return text_.substr(at_).starts_with(s); }
  char peek(std::size_t ahead = 0) const {
    return at_ + ahead < text_.size() ? text_[at_ + ahead] : '\0';
  }
  void advance(std::size_t n = 1) {
    const std::size_t end = std::min(text_.size(), at_ + n);
    line_ += static_cast<std::size_t>(std::count(text_.begin() + static_cast<long>(at_),
                                                 text_.begin() + static_cast<long>(end), '\n'));
    at_ = end;
  }
  /// Moves past the next `marker` (to the end when there is none: cut()).
  void skipPast(std::string_view marker) {
    const std::size_t found = text_.find(marker, at_);
    cut_ = found == std::string_view::npos;
    advance(cut_ ? text_.size() - at_ : found - at_ + marker.size());
  }
  /// Moves past the '>' that ends a tag, quoted values included; true if it was "/>".
  bool skipTag() {
    char quote = '\0';
    char last = '\0';
    while (!done()) {
      const char c = peek();
      advance();
      if (quote != '\0') {
        if (c == quote) quote = '\0';
      } else if (c == '"' || c == '\'') {
        quote = c;
      } else if (c == '>') {
        return last == '/';
      }
      last = c;
    }
    cut_ = true;
    return false;
  }
  /// Whether the text ended inside what the last skip was skipping.
  bool cut() const { return cut_; }
  std::size_t line() const { return line_; }

 private:
  std::string_view text_;
  std::size_t at_ = 0;
  std::size_t line_ = 1;
  bool cut_ = false;
};

/// Moves the cursor past the tag, comment, CDATA section or declaration it is at; true when
/// `open` asks the walk to stop.
template <typename Open, typename Close>
bool walkOne(Cursor& cursor, Open& open, Close& close) {
  if (cursor.startsWith("<!--")) {
    cursor.skipPast("-->");
  } else if (cursor.startsWith("<![CDATA[")) {
    cursor.skipPast("]]>");
  } else if (cursor.peek(1) == '?') {
    cursor.skipPast("?>");
  } else if (cursor.peek(1) == '!') {
    cursor.skipTag();
  } else if (cursor.peek(1) == '/') {
    cursor.skipTag();
    close();
  } else {
    const std::size_t line = cursor.line();
    return !cursor.skipTag() && !cursor.cut() && open(line);
  }
  return false;
}

/// Walks `text`'s tags: `open(line)` for each element opened and not closed in its own tag (it
/// returns true to stop the walk), `close()` for each closing tag, and `cut(line)` for a tag,
/// comment, CDATA section or declaration that the text ends inside of.
template <typename Open, typename Close, typename Cut>
void walkElements(std::string_view text, Open open, Close close, Cut cut) {
  Cursor cursor(text);
  while (!cursor.done()) {
    if (cursor.peek() != '<') {
      cursor.advance();
      continue;
    }
    const std::size_t start = cursor.line();
    if (walkOne(cursor, open, close)) return;
    if (cursor.cut()) cut(start);
  }
}

}  // namespace

std::optional<std::size_t> xmlNestedBeyond(std::string_view text, std::size_t limit) {
  std::size_t depth = 0;
  std::optional<std::size_t> beyond;
  walkElements(
      text,
      [&](std::size_t line) {
        if (++depth > limit) beyond = line;
        return beyond.has_value();
      },
      [&] { depth -= depth > 0 ? 1 : 0; }, [](std::size_t) {});
  return beyond;
}

std::optional<std::size_t> xmlOpenAtEnd(std::string_view text) {
  std::vector<std::size_t> open;
  walkElements(
      text,
      [&](std::size_t line) {
        open.push_back(line);
        return false;
      },
      [&] {
        if (!open.empty()) open.pop_back();
      },
      [&](std::size_t line) { open.push_back(line); });
  return open.empty() ? std::nullopt : std::optional<std::size_t>(open.back());
}

}  // namespace common
