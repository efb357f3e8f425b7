# Converts a SPIR-V binary into a C++ source file that defines the words as an array:
#   cmake -DINPUT=x.spv -DOUTPUT=x.spv.cpp -DNAME=symbol -P EmbedSpirv.cmake
# defines `extern const std::uint32_t NAME[]` and `extern const std::size_t NAME_words`.
file(READ "${INPUT}" hex HEX)
string(LENGTH "${hex}" hex_length)
math(EXPR remainder "${hex_length} % 8")
if(hex_length EQUAL 0 OR NOT remainder EQUAL 0)
  message(FATAL_ERROR "${INPUT} is not a SPIR-V module (size not a multiple of 4 bytes)")
endif()
# SPIR-V words are stored little-endian: bytes b0 b1 b2 b3 form 0xb3b2b1b0.
string(REGEX REPLACE "(..)(..)(..)(..)" "0x\\4\\3\\2\\1u," words "${hex}")
string(REGEX REPLACE "((0x[0-9a-f]+u,){8})" "\\1\n" words "${words}")
math(EXPR word_count "${hex_length} / 8")
file(WRITE "${OUTPUT}"
     "// Generated from ${INPUT} by cmake/EmbedSpirv.cmake; do not edit.\n"
     "#include <cstddef>\n#include <cstdint>\n"
     "extern const std::uint32_t ${NAME}[];\nextern const std::size_t ${NAME}_words;\n"
     "alignas(4) const std::uint32_t ${NAME}[] = {\n${words}\n};\n"
     "const std::size_t ${NAME}_words = ${word_count};\n")
