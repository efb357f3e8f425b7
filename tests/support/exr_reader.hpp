// tests/support/exr_reader.hpp — the OpenEXR reader the tests check written files with: the
// library's read_exr (ocean/io.hpp), which shares no code with the writer.
#pragma once

#include "ocean/io.hpp"
