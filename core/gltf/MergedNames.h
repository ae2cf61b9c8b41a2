#pragma once
// The morph-target names `avatar reduce --names merged` gives its keys. Blender truncates names over
// 63 bytes (and FBX, Unity and others follow its files), so a merged name must fit in 63 bytes and
// stay readable and unique; the full member list lives in the extras (core/gltf/OwnOutput.h).
// - A key of one member keeps its member's name (the file's own name, whatever its length).
// - A key of several members: the first member's name, then the others without the prefix all
//   members share up to a separator ('_', '.', '-', ':', ' '), joined with '+':
//   viseme_PP + viseme_FF + viseme_TH -> "viseme_PP+FF+TH", Fcl_MTH_A + Fcl_MTH_E -> "Fcl_MTH_A+E".
// - Over 63 bytes: as many leading members as fit, then "+<n> more" ("Mouth_Open_Wide+Pucker+3 more"),
//   the first member cut at a code point boundary when even it does not fit.
// - A name another target already has (or another key got) gets "~2", "~3", ... (cut to fit).
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace vl {

inline constexpr std::size_t kMaxTargetNameBytes = 63;

// One name per key (`members` per key, in key order); `taken`: names of the targets kept as they are.
std::vector<std::string> mergedTargetNames(const std::vector<std::vector<std::string>>& members,
                                           const std::vector<std::string>& taken);

// `text` cut to at most `bytes` bytes without splitting a UTF-8 code point.
std::string utf8Prefix(std::string_view text, std::size_t bytes);

} // namespace vl
