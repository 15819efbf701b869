#pragma once
/// \file
/// The page of `prt view`: plain HTML and JavaScript kept in src/view/page/ and embedded in the
/// binary by the build (scripts/embed-files.cmake, view/embedded_files.h), so the server never
/// reads a file from disk and the page needs nothing from the network.

#include <optional>
#include <string>
#include <string_view>

namespace prt {

struct PageFile {
  std::string_view body;
  const char* type;  ///< its Content-Type
};

/// The page file served at URL path `path` ("/" is index.html, "/view.js" the script), or
/// nullopt for any other path: nothing but the embedded files is ever served by name.
std::optional<PageFile> FindPageFile(const std::string& path);

}  // namespace prt
