#pragma once
/// \file
/// A word as a POSIX shell reads it back: for the command lines prt prints for a user to paste
/// (`prt view`'s `prt render` line).

#include <string>

namespace prt {

/// `word` as it is when the shell passes it through unchanged (letters, digits and
/// `_-+=.,/:@%`, not empty), else in single quotes, each quote inside written `'\''`.
/// `sky.hdr` stays `sky.hdr`; `my sky.hdr` becomes `'my sky.hdr'`; `it's` becomes `'it'\''s'`.
std::string ShellWord(const std::string& word);

}  // namespace prt
