#pragma once
// The body of the runtime fuzz target, shared by the libFuzzer entry (clang) and the deterministic
// mutation test (any compiler): load arbitrary bytes; when they load, animate every key.
#include <cstddef>
#include <cstdint>
#include <string>

namespace vl::test {

// Loads the bytes as they are and with their CRC-32 repaired; returns 1 when either loaded. Aborts when a
// loaded package produces inconsistent results (a bug the fuzzer should report).
int fuzzRuntimePackage(const std::uint8_t* data, std::size_t size);

// Rewrites the header's payload CRC-32 to match the bytes (no-op for inputs shorter than a header),
// so deliberately inconsistent payloads reach the structural checks behind the CRC.
void repairPayloadCrc(std::uint8_t* data, std::size_t size);
void repairPayloadCrc(std::string& bytes);

} // namespace vl::test
