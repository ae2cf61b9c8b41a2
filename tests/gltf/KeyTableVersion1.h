#pragma once
// The key table layout `avatar reduce` wrote before version 2 (core/gltf/KeyTable.h), made from a
// version-2 output: the readers must keep reading the files VisemeLab wrote then.
#include <string>

namespace vl::test {

// The GLB with its extras rewritten to version 1: the root extras.visemelab with "version": 1, every
// key named and the touched meshes listed; on each mesh with keys, "phonemeToTarget", "visemeKeys"
// as [{key, name, members, frequency, targets}] and "targetAliases" naming every viseme of the mesh.
std::string withKeyTableVersion1(const std::string& glb);

} // namespace vl::test
