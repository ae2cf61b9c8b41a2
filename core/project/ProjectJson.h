#pragma once
// Internal to core/project: conversion between Project sections and JSON (current version).
// Readers validate everything they read and throw InputError "<JSON path>: <what>".
#include "core/io/JsonRead.h"
#include "core/project/Project.h"

#include <filesystem>
#include <string>
#include <vector>

namespace vl {

// What section readers need beyond their JSON node.
struct ProjectReadContext {
    std::filesystem::path folder;  // folder of the project file, for relative mesh paths
    bool checkFiles = true;        // referenced mesh files must exist
    int version = kProjectVersion; // of the document being read (>= 1: older ones are migrated first)
};

// A mesh or avatar file named at `node`: must exist when context.checkFiles.
std::filesystem::path fileFromJson(const JsonNode& node, const ProjectReadContext& context);

// Mesh parts: [[u, v], ...] and [[a, b, c], ...] (0-based indices below vertexCount, distinct, at
// least one triangle).
Json uvArrayToJson(const std::vector<Vec2>& uvs);
Json trianglesToJson(const std::vector<Triangle>& triangles);
std::vector<Triangle> trianglesFromJson(const JsonNode& node, std::size_t vertexCount);

Json projectToJson(const Project& project);
Project projectFromJson(const JsonNode& root, const ProjectReadContext& context); // version already checked

Json frequenciesToJson(const FrequencySource& frequencies);
FrequencySource frequenciesFromJson(const JsonNode& node, const std::vector<std::string>& visemeNames);

// Sampled grids equal to a built-in face geometry are written as {"builtin": name, ...}.
// The face's (u,v) mesh ("domain") is allowed from version 2 on (context.version).
Json deformationToJson(const ProjectDeformation& deformation);
ProjectDeformation deformationFromJson(const JsonNode& node, const ProjectReadContext& context);

// Criteria without a section in the file keep their default thresholds.
Json refinementToJson(const CriterionSettings& settings);
CriterionSettings refinementFromJson(const JsonNode& node);

// The reduction's optional "constraints" (written only when there are any).
Json constraintsToJson(const ConstraintNames& constraints);
ConstraintNames constraintsFromJson(const JsonNode& node, const std::vector<std::string>& visemeNames);

// The rest model's fields (rest, restViseme, a rest-free result) need version 3 (context.version).
Json reductionToJson(const ProjectReduction& reduction, const std::vector<std::string>& visemeNames);
ProjectReduction reductionFromJson(const JsonNode& node, const std::vector<std::string>& visemeNames,
                                   const ProjectReadContext& context);
// Whether the reduction section holds anything of version 3 (the rest model).
bool reductionNeedsVersion3(const ProjectReduction& reduction);

// The optional "speech" section (written only when it differs from the defaults).
Json speechToJson(const SpeechSettings& speech);
SpeechSettings speechFromJson(const JsonNode& node);
// The optional "avatar" object: {"file": "avatar.glb", "targets": "Fcl_MTH_[AIUEO]"}.
Json avatarToJson(const ProjectAvatar& avatar);
ProjectAvatar avatarFromJson(const JsonNode& node, const ProjectReadContext& context);

// Versions kFirstLayoutVersion..kProjectVersion share one layout (later versions only add optional
// fields) and are read as they are; older versions are migrated to kFirstLayoutVersion first.
inline constexpr int kFirstLayoutVersion = 1;

// Version handling: the version of a document, and the upgrade of an older one to the current layout.
int projectVersionOf(const JsonNode& root); // checks "format" too; refuses newer versions
Json migrateProjectJson(const JsonNode& root, int fromVersion);

} // namespace vl
