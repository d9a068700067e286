# SPDX-License-Identifier: MIT
# raypoint_ini_to_man(INI_FILE OUT_VAR): the keys of a `raypoint print-config` INI file as troff
# for raypoint.ini(5): one .SS per section, one .TP per key with its description, allowed values
# and default. The file's layout is print-config's: "# description" lines, then
# "# allowed: A, default: D", then "key = value".

# Escapes text for troff: backslashes, and a leading dot or quote that would read as a request.
function(_raypoint_troff_escape text out_var)
  string(REPLACE "<raypoint-semicolon>" ";" text "${text}")
  string(REPLACE "\\" "\\e" text "${text}")
  string(REGEX REPLACE "^([.'])" "\\\\&\\1" text "${text}")
  set(${out_var} "${text}" PARENT_SCOPE)
endfunction()

function(raypoint_ini_to_man ini_file out_var)
  # One list element a line. A semicolon in a description would split its line as a CMake
  # list separator, so it travels as a placeholder until the line is taken apart.
  file(READ ${ini_file} content)
  string(REPLACE ";" "<raypoint-semicolon>" content "${content}")
  string(REPLACE "\n" ";" lines "${content}")
  set(troff "")
  set(section "")
  set(description "")
  set(allowed "")
  foreach(line IN LISTS lines)
    if(line MATCHES "^\\[([a-z_]+)\\]$")
      set(section ${CMAKE_MATCH_1})
      string(APPEND troff ".SS [${section}]\n")
      set(description "")
      set(allowed "")
    elseif(section STREQUAL "")
      # The file's header comment, before the first section: not about one key.
    elseif(line MATCHES "^# allowed: (.*)$")
      set(allowed "${CMAKE_MATCH_1}")
    elseif(line MATCHES "^# ?(.*)$")
      _raypoint_troff_escape("${CMAKE_MATCH_1}" text)
      if(description STREQUAL "")
        set(description "${text}")
      else()
        string(APPEND description "\n${text}")
      endif()
    elseif(line MATCHES "^([a-z_0-9]+) *=")
      string(APPEND troff ".TP\n.B ${section}.${CMAKE_MATCH_1}\n")
      if(NOT description STREQUAL "")
        string(APPEND troff "${description}\n")
      endif()
      if(NOT allowed STREQUAL "")
        _raypoint_troff_escape("${allowed}" text)
        string(APPEND troff ".br\nAllowed: ${text}\n")
      endif()
      set(description "")
      set(allowed "")
    endif()
  endforeach()
  set(${out_var} "${troff}" PARENT_SCOPE)
endfunction()
