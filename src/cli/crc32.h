// Copyright contactlaws authors.
//
// CRC-32 as zlib's crc32_z computes it (ISO 3309 / ITU-T V.42, the ZIP
// format's), by carry-less multiplication where the processor has it
// (PCLMULQDQ): a 104 MB trajectory's took 3.9 instructions a byte through
// zlib's tables (0.40 G; about 40 ms of the run, perf), 0.5 folded (0.05 G;
// about 12 ms). Elsewhere, and for the bytes a fold leaves, zlib's own.

#ifndef CONTACTLAWS_CLI_CRC32_H_
#define CONTACTLAWS_CLI_CRC32_H_

#include <cstddef>
#include <cstdint>

namespace contactlaws::cli {

// The CRC-32 of crc's message followed by size bytes at data, as
// crc32_z(crc, data, size) returns it (crc 0 for an empty message).
uint32_t Crc32(uint32_t crc, const void* data, size_t size);

// Whether Crc32 folds by carry-less multiplication on this processor.
bool Crc32Folds();

}  // namespace contactlaws::cli

#endif  // CONTACTLAWS_CLI_CRC32_H_
