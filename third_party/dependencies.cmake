# Imported targets for the Debian packages prt uses. See third_party/README.md for versions,
# licences and why each is here. Every target is marked SYSTEM so our warnings stay on our code.

find_package(glm CONFIG REQUIRED)                 # libglm-dev
find_package(tinyobjloader CONFIG REQUIRED)       # libtinyobjloader-dev
find_package(nanoflann CONFIG REQUIRED)           # libnanoflann-dev
find_package(doctest CONFIG REQUIRED)             # doctest-dev
find_package(OpenEXR CONFIG REQUIRED)             # libopenexr-dev
find_package(ZLIB REQUIRED)                       # zlib1g-dev (PNG deflate)
find_package(nlohmann_json CONFIG REQUIRED)       # nlohmann-json3-dev (prt view's JSON)
find_package(PkgConfig REQUIRED)
pkg_check_modules(PRT_HTTPLIB REQUIRED IMPORTED_TARGET cpp-httplib)  # libcpp-httplib-dev (prt view)

# stb ships no CMake config; Debian builds the implementations into libstb.
find_path(PRT_STB_INCLUDE_DIR stb_image.h PATH_SUFFIXES stb REQUIRED)
find_library(PRT_STB_LIBRARY NAMES stb REQUIRED)

function(prt_system_target name)
  add_library(${name} INTERFACE IMPORTED GLOBAL)
endfunction()

prt_system_target(prt::glm)
target_link_libraries(prt::glm INTERFACE glm::glm)
target_compile_definitions(prt::glm INTERFACE GLM_FORCE_XYZW_ONLY GLM_ENABLE_EXPERIMENTAL)

prt_system_target(prt::stb)
target_include_directories(prt::stb SYSTEM INTERFACE ${PRT_STB_INCLUDE_DIR})
target_link_libraries(prt::stb INTERFACE ${PRT_STB_LIBRARY} ZLIB::ZLIB)

prt_system_target(prt::tinyobjloader)
target_link_libraries(prt::tinyobjloader INTERFACE tinyobjloader::tinyobjloader)

prt_system_target(prt::nanoflann)
target_link_libraries(prt::nanoflann INTERFACE nanoflann::nanoflann)

prt_system_target(prt::doctest)
target_link_libraries(prt::doctest INTERFACE doctest::doctest)

prt_system_target(prt::openexr)
target_link_libraries(prt::openexr INTERFACE OpenEXR::OpenEXR)

# Header only: the JSON that prt view's scene answers the page with (src/app/view_scene.cpp).
prt_system_target(prt::json)
target_link_libraries(prt::json INTERFACE nlohmann_json::nlohmann_json)

# Debian builds cpp-httplib as a library (with TLS, zlib and brotli, which prt does not use):
# its pkg-config flags make the header declare the classes as the library was built.
prt_system_target(prt::httplib)
target_link_libraries(prt::httplib INTERFACE PkgConfig::PRT_HTTPLIB)
