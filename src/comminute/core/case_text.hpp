#pragma once
// Checks of a case file's text before toml++ parses it, and of its keys after (core/ internal, used
// by CaseFile and by readers of other TOML files).
#include <string>
#include <string_view>

#include <toml++/toml.h>

namespace comminute {

// Well-formed UTF-8 without control characters, and non-ASCII only inside strings and comments
// (toml++ 3.3.0 has undefined behaviour otherwise). Throws InputError naming the line.
void check_case_text(std::string_view text, const std::string& name);
// Keys are names: no quoted key holding '.', '[' or ']', no empty key. Throws InputError.
void check_case_keys(const toml::table& t, const std::string& name, const std::string& base = "");

}  // namespace comminute
