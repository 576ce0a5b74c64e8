// Text read from a file, made safe to print on a terminal. A results folder is untrusted input
// (docs/schema.md, trust model): a claim id, a statement or an overridden parameter in it may hold
// terminal escapes (ESC [ 2 J clears the screen, OSC sequences set the title or a hyperlink),
// carriage returns that overwrite a verdict, or bidi overrides that reorder a line. Everything
// `check` and the refusals print from a file goes through printable().
#pragma once
#include <string>
#include <string_view>

namespace granrepro {

// `text` with every control character (C0, DEL, C1), bidi control and byte of invalid UTF-8
// written as an escape: \n, \t, \r, \e, \xNN (a byte) or \u{NNNN} (a code point). Valid UTF-8
// printing text, backslashes included, is returned unchanged, so ordinary names print as before.
std::string printable(std::string_view text);

} // namespace granrepro
