# Writes a C++ source defining `std::string_view SYMBOL()` that returns the bytes of INPUT, as a
# raw string literal (the files embedded are text: a script, a licence). An INPUT that is empty
# or absent gives an empty view. Run as: cmake -DINPUT=... -DOUTPUT=... -DSYMBOL=... -P this file.
# SYMBOL may be qualified by a namespace written as NAMESPACE.
if(NOT DEFINED OUTPUT OR NOT DEFINED SYMBOL)
  message(FATAL_ERROR "embed_text.cmake: OUTPUT and SYMBOL are required")
endif()
set(text "")
if(DEFINED INPUT AND NOT INPUT STREQUAL "" AND EXISTS "${INPUT}")
  file(READ "${INPUT}" text)
endif()
# The literal's delimiter must not occur in the text, or the literal would end early.
set(delimiter "embed_")
string(FIND "${text}" ")${delimiter}\"" clash)
if(NOT clash EQUAL -1)
  message(FATAL_ERROR "embed_text.cmake: ${INPUT} contains the raw string's delimiter")
endif()
set(content "// Generated from ${INPUT} by cmake/embed_text.cmake: do not edit.\n")
string(APPEND content "#include <string_view>\n\nnamespace ${NAMESPACE} {\n\n")
string(APPEND content "std::string_view ${SYMBOL}() {\n")
string(APPEND content "  static constexpr char text[] = R\"${delimiter}(")
string(APPEND content "${text}")
string(APPEND content ")${delimiter}\";\n  return {text, sizeof(text) - 1};\n}\n\n}\n")
# Rewritten only when changed, so a reconfigure does not rebuild what depends on it.
set(old "")
if(EXISTS "${OUTPUT}")
  file(READ "${OUTPUT}" old)
endif()
if(NOT old STREQUAL content)
  file(WRITE "${OUTPUT}" "${content}")
endif()
