// Text and key checks a case file passes before and after toml++ parses it.
#include "comminute/core/case_text.hpp"

#include <fmt/format.h>

#include <cstdint>
#include <string>

#include "comminute/core/error.hpp"

namespace comminute {

namespace {

// toml++ 3.3.0 (Debian 12's) has undefined behaviour on some malformed non-ASCII input (fixed
// upstream in 3.4): the text must be well-formed UTF-8 (no overlong forms, surrogates or code
// points above U+10FFFF) and free of NUL and other control characters but tab, CR and LF before
// the parser sees it.
void check_utf8(std::string_view text, const std::string& name) {
  long line = 1;
  for (std::size_t i = 0; i < text.size();) {
    const auto c = static_cast<unsigned char>(text[i]);
    if (c == '\n') ++line;
    if (c < 0x80) {
      if ((c < 0x20 && c != '\t' && c != '\n' && c != '\r') || c == 0x7f)
        throw InputError(name, "", line,
                         fmt::format("control character 0x{:02x} in the text", unsigned(c)));
      ++i;
      continue;
    }
    std::size_t len = 0;
    std::uint32_t cp = 0;
    if (c >= 0xc2 && c <= 0xdf) {
      len = 2;
      cp = c & 0x1fu;
    } else if (c >= 0xe0 && c <= 0xef) {
      len = 3;
      cp = c & 0x0fu;
    } else if (c >= 0xf0 && c <= 0xf4) {
      len = 4;
      cp = c & 0x07u;
    }
    bool ok = len > 0 && i + len <= text.size();
    for (std::size_t k = 1; ok && k < len; ++k) {
      const auto cc = static_cast<unsigned char>(text[i + k]);
      ok = (cc & 0xc0u) == 0x80u;
      cp = (cp << 6) | (cc & 0x3fu);
    }
    if (ok)
      ok = !(len == 3 && cp < 0x800) && !(len == 4 && (cp < 0x10000 || cp > 0x10ffff)) &&
           !(cp >= 0xd800 && cp <= 0xdfff);
    if (!ok) throw InputError(name, "", line, "the text is not valid UTF-8");
    i += len;
  }
}

// toml++ 3.3.0 classifies characters outside strings (whitespace, value ends) with a table that
// reaches __builtin_unreachable for many code points (U+00A1-U+0499, U+2F3E-U+3337): undefined
// behaviour, fixed upstream in 3.4. TOML allows non-ASCII text only in strings and comments, so
// anything else is refused before the parser sees it, as is a non-ASCII character after a
// backslash in a string (an escape toml++ would classify the same way).
void check_non_ascii_placement(std::string_view text, const std::string& name) {
  enum class In { code, comment, basic, literal, ml_basic, ml_literal } in = In::code;
  long line = 1;
  // A quote opens a string only where TOML allows one (after '=', '[', ',', '{', '.' or at the
  // start of a line); elsewhere (e.g. right after a malformed number) toml++ keeps classifying the
  // characters that follow as code, so they must stay ASCII.
  char previous = '\n';  // last non-blank character of code
  // Whether code is in a value (from '=' to the end of its line, or of its brackets): there a '.'
  // belongs to a number or a malformed value, never to a dotted key, so a quote after it opens no
  // string (`x = 0."...` is a malformed float to toml++). `open`: the value's unclosed '[' and
  // '{'; in an inline table a key follows '{' and ','.
  bool value = false;
  std::string open;
  auto opens_string = [&] {
    return previous == '\n' || previous == '=' || previous == '[' || previous == ',' ||
           previous == '{' || (previous == '.' && !value);
  };
  auto end_of_line = [&] {
    previous = '\n';
    if (open.empty()) value = false;
  };
  auto at = [&](std::size_t i, std::string_view what) {
    return text.substr(i, what.size()) == what;
  };
  auto refuse = [&](const char* what) { throw InputError(name, "", line, what); };
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    const bool non_ascii = (static_cast<unsigned char>(c) & 0x80u) != 0;
    if (c == '\n') ++line;
    switch (in) {
      case In::code:
        if (non_ascii) refuse("non-ASCII character outside a string or comment");
        if (c == '=') {
          value = true;
        } else if (value && (c == '[' || c == '{')) {
          open.push_back(c);
          value = c == '[';
        } else if (!open.empty() && (c == ']' || c == '}')) {
          open.pop_back();
          value = true;
        } else if (c == ',' && !open.empty()) {
          value = open.back() == '[';
        } else if (c == '\n' && open.empty()) {
          value = false;
        }
        if ((c == '"' || c == '\'') && !opens_string()) {
          previous = c;
          break;
        }
        if (c != ' ' && c != '\t' && c != '\r') previous = c;
        if (c == '#') in = In::comment;
        if (c == '"') {
          if (at(i, "\"\"\"")) {
            in = In::ml_basic;
            i += 2;
          } else {
            in = In::basic;
          }
        }
        if (c == '\'') {
          if (at(i, "'''")) {
            in = In::ml_literal;
            i += 2;
          } else {
            in = In::literal;
          }
        }
        break;
      case In::comment:
        if (c == '\n') {
          in = In::code;
          end_of_line();
        }
        break;
      case In::basic:
      case In::ml_basic:
        if (c == '\\') {
          // an escape, or a line-ending backslash: the next non-blank character is classified
          std::size_t j = i + 1;
          while (in == In::ml_basic && j < text.size() &&
                 (text[j] == ' ' || text[j] == '\t' || text[j] == '\r' || text[j] == '\n'))
            ++j;
          if (j < text.size() && (static_cast<unsigned char>(text[j]) & 0x80u))
            refuse("non-ASCII character after a backslash in a string");
          if (j == i + 1 && i + 1 < text.size()) {  // the escaped character
            if (text[i + 1] == '\n') ++line;
            ++i;
          }
          break;
        }
        if (in == In::basic && (c == '"' || c == '\n')) {
          in = In::code;
          if (c == '\n') end_of_line();
        }
        if (in == In::ml_basic && at(i, "\"\"\"")) {
          while (i + 1 < text.size() && text[i + 1] == '"') ++i;  // up to two quotes of content
          in = In::code;
        }
        break;
      case In::literal:
        if (c == '\'' || c == '\n') {
          in = In::code;
          if (c == '\n') end_of_line();
        }
        break;
      case In::ml_literal:
        if (at(i, "'''")) {
          while (i + 1 < text.size() && text[i + 1] == '\'') ++i;
          in = In::code;
        }
        break;
    }
  }
}

}  // namespace

void check_case_text(std::string_view text, const std::string& name) {
  check_utf8(text, name);
  check_non_ascii_placement(text, name);
}

// Keys are names: a quoted key holding '.', '[' or ']' (e.g. "simulation.end_time" = 5) would
// look like a key path and be mistaken for another key; an empty key names nothing.
void check_case_keys(const toml::table& t, const std::string& name, const std::string& base) {
  for (const auto& [k, v] : t) {
    const std::string_view key = k.str();
    const std::string path = base.empty() ? std::string(key) : base + "." + std::string(key);
    if (key.empty() || key.find_first_of(".[]") != std::string_view::npos)
      throw InputError(name, path, static_cast<long>(k.source().begin.line),
                       key.empty() ? "empty key"
                                   : "a key may not contain '.', '[' or ']' (a quoted dotted key "
                                     "is not a key path: write [table] and key = value)");
    if (auto sub = v.as_table()) check_case_keys(*sub, name, path);
    if (auto arr = v.as_array())
      for (std::size_t i = 0; i < arr->size(); ++i)
        if (auto et = arr->get(i)->as_table())
          check_case_keys(*et, name, fmt::format("{}[{}]", path, i));
  }
}

}  // namespace comminute
