#include "view/page.h"

#include "view/embedded_files.h"

namespace prt {

std::optional<PageFile> FindPageFile(const std::string& path) {
  const std::string name = path == "/" ? "index.html" : path.substr(path.empty() ? 0 : 1);
  if (path.empty() || path[0] != '/') return std::nullopt;
  for (std::size_t i = 0; i < embedded::kFileCount; ++i) {
    const embedded::File& file = embedded::kFiles[i];
    if (name != file.name) continue;
    const std::string_view body(reinterpret_cast<const char*>(file.bytes), file.size);
    const bool html = name.size() > 5 && name.compare(name.size() - 5, 5, ".html") == 0;
    return PageFile{body, html ? "text/html; charset=utf-8" : "text/javascript; charset=utf-8"};
  }
  return std::nullopt;
}

}  // namespace prt
