// The SHA-256 of what a render reads from disk (the glTF file, the files its
// buffers and images name, the environment map), so that the parts and
// checkpoints of one render can be told from another render's.
#pragma once

#include <string>
#include <string_view>

namespace lensrt {

// Hex SHA-256 over each file's name (as given) and content, in a fixed order.
// `environmentMap` may be empty. The scene's URIs are resolved as the loader
// resolves them (SceneFileAccess: its folder only unless `allowExternalFiles`).
// Throws InputError when a file cannot or may not be read.
std::string sceneDigest(const std::string& sceneFile, const std::string& environmentMap,
                        bool allowExternalFiles);

// Hex SHA-256 of `bytes`.
std::string sha256Hex(std::string_view bytes);

}  // namespace lensrt
