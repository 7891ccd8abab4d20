// Checks a scene file's content before a VTK reader is called (SPEC, Scenes:
// bad input is refused with a clear message, never a crash). VTK's readers
// trust their input: vtkPLYReader indexes past a line's words when an ASCII
// line holds fewer values than the header declares (a segfault), and frees a
// stale pointer on a blank line; vtkSTLReader, vtkDataSetReader and the XML
// readers allocate what a header declares before reading it. So the format is
// told by content (magic and header sniffing: a UTF-16 or binary .obj, a .ply
// whose header is malformed or names a type VTK does not know), and every
// count in a header is checked against the bytes the file holds.
//
// Errors are "FILE: what, where, the value", e.g. "scene.ply: header declares
// 4294967295 vertices of 12 bytes (51.5 GB) but the file holds 1234 bytes
// after the header".
#ifndef vtkradiosity_SceneFileCheck_h
#define vtkradiosity_SceneFileCheck_h

#include <string>

namespace radiosity
{
namespace cli
{
/// The whole file, or false with `error` set (missing, unreadable, a directory).
bool ReadFileBytes(const std::string& file, std::string& bytes, std::string& error);

/// A .obj (or .mtl) must be 8-bit text: UTF-16/32 (by byte order mark or NUL
/// bytes) and binary content are refused, naming the offset of the first bad byte.
bool CheckObjText(const std::string& file, const std::string& bytes, std::string& error);

/**
 * A .ply as vtkPLYReader (VTK 9.2) can read it without crashing: "ply", one
 * format line (ascii / binary_little_endian / binary_big_endian), elements with
 * counts that fit in an int, properties of VTK's types, `end_header`; a
 * `vertex` element with scalar x, y, z before the `face` element (whose
 * vertex_indices list, if any, holds at most 255 indices, each in range), and
 * no other element before them. The body is walked: an ASCII line per element
 * with exactly the values the header declares, no line longer than VTK's 4095
 * characters; a binary body at least as long as the header declares. On
 * success `bytes` may be amended for the reader (a final line end added).
 */
bool CheckPly(const std::string& file, std::string& bytes, std::string& error);

/// A binary STL (as vtkSTLReader tells it: vtksys' text detection) must hold
/// exactly 84 + 50 x its declared triangle count bytes.
bool CheckStl(const std::string& file, const std::string& bytes, std::string& error);

/// Legacy .vtk: the "# vtk DataFile Version" magic, ASCII or BINARY, and every
/// count on a POINTS, cell, attribute or FIELD line small enough for the bytes
/// left in the file (a binary value takes its type's size, an ASCII one at
/// least 2 characters).
bool CheckLegacyVtk(const std::string& file, const std::string& bytes, std::string& error);

/// VTK XML (.vtp, .vtu, .vtm...): starts with '<' (after a BOM or blanks), and
/// NumberOfPoints / NumberOfCells / NumberOfPolys... counts small enough for
/// the file (uncompressed: 1 byte per value at least; compressed: the
/// compressor's best ratio, 1032:1 for zlib, 255:1 for lz4, 7000:1 for lzma).
bool CheckXmlVtk(const std::string& file, const std::string& bytes, std::string& error);

/// An ASCII number as VTK's readers read it (istream >>): an optional sign and
/// digits, for floating-point types also a fraction and an exponent; no nan,
/// inf or hexadecimal (the stream fails on them and leaves the rest unread).
bool IsAsciiNumber(const std::string& token, bool integer);

/// The byte count in words: "1234 bytes", "51.5 GB".
std::string ByteSize(double bytes);
}
}

#endif
