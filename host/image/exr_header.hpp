// A structural check of an OpenEXR file's header before OpenEXR reads it: OpenEXR 3.1 trusts
// each attribute's size field and allocates it (a 1.4 KiB file from fuzz_image made it allocate
// 1.9 GiB for one string attribute), so a damaged or hostile header must be refused first.
#pragma once

#include "util/error.hpp"

#include <filesystem>

namespace pl::image {

// For a file that starts with the OpenEXR magic number (any other file passes unread past its
// first 4 bytes): walks the header(s) (one, or every part's of a multi-part file) as the OpenEXR file layout
// defines them: attributes of name\0 type\0 int32 size and size bytes, ended by an empty name.
// An error when a name runs past 255 characters, a size is negative or reaches past the end of
// the file, or the header never ends.
Status check_exr_header(const std::filesystem::path& file);

} // namespace pl::image
