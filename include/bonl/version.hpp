#pragma once
// The one place bonl's version is written: CMakeLists.txt reads it from here.

#define BONL_VERSION_MAJOR 0
#define BONL_VERSION_MINOR 1
#define BONL_VERSION_PATCH 0

namespace bonl {
inline constexpr int version_major = BONL_VERSION_MAJOR;  ///< bonl's major version
inline constexpr int version_minor = BONL_VERSION_MINOR;  ///< bonl's minor version
inline constexpr int version_patch = BONL_VERSION_PATCH;  ///< bonl's patch version
}  // namespace bonl
