#pragma once
// Internal to the inertia layer: the checks of a PLY file that load_mesh (mesh_io.hpp) makes before assimp
// reads it. assimp 5.2.5 trusts the file: it loops without end on some malformed headers, and it allocates
// for every count the file declares — the element counts of the header and the length of each list in the
// body (a face's vertex count) — before it finds that the file does not hold that many values (found by
// fuzzing: a 300-byte binary PLY whose first face declares 3·10^8 indices made it allocate 2.4 GB).
//
// The checks, each refused with one line naming the file, the header line or element, and what was expected:
//  * the header: "ply", then `format ascii|binary_little_endian|binary_big_endian V`, `comment ...`,
//    `obj_info ...`, `element NAME N` (N at most the file's size in bytes), `property TYPE NAME` or
//    `property list TYPE TYPE NAME` with TYPE one of PLY's (char uchar short ushort int uint float double,
//    or int8 uint8 int16 uint16 int32 uint32 float32 float64), up to `end_header`, within the first 64 KiB;
//  * a binary body: walked element by element, value by value, as the header declares it (list lengths read
//    in the file's byte order): every list length is a whole number >= 0 and the values it declares, like all
//    declared values, lie within the file;
//  * an ASCII body: walked token by token; every list length is a whole number >= 0 and at most the number
//    of values the rest of the file can hold (each value takes a character and a separator). A body that ends
//    early, or a token that is not a number, is left to assimp, which reports it.
// The walk reads the file once, in blocks of 1 MiB (memory independent of the file's size).
#include <string>

namespace poinsot::inertia::detail {

/// Checks the PLY file `path` as above. Throws InvalidInput (one line) when a check fails.
void check_ply_file(const std::string& path);

}  // namespace poinsot::inertia::detail
