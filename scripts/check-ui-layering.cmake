# The editor's layering, checked from its sources (the core's: check-layering.cmake). Each layer of
# ui/ is its own library (ui/CMakeLists.txt) and may include only the layers below it:
#   ui/session   core/, ui/session/                                  no ImGui, GL or GLFW
#   ui/probe     nothing of ui/ (the test probe every drawing layer records into)
#   ui/render    core/, ui/probe/, ui/render/, ui/UiScale.h          no session, widgets or panels
#   ui/audio     ui/audio/
#   ui/widgets   core/, ui/session/, ui/probe/, ui/render/, ui/widgets/, ui/UiScale.h
# (ui/panels and the window's files above them may include any layer.) Fails naming the file, the
# line's include and the rule.
#
#   cmake -DROOT=<source tree> -P scripts/check-ui-layering.cmake
cmake_minimum_required(VERSION 3.20)
if(NOT DEFINED ROOT)
  message(FATAL_ERROR "check-ui-layering: -DROOT=... is required")
endif()

set(ALLOWED_session "core/" "ui/session/")
set(ALLOWED_probe "ui/probe/")
set(ALLOWED_render "core/" "ui/probe/" "ui/render/" "ui/UiScale.h")
set(ALLOWED_audio "ui/audio/")
set(ALLOWED_widgets "core/" "ui/session/" "ui/probe/" "ui/render/" "ui/widgets/" "ui/UiScale.h")
# System headers a layer must not reach: the session is the editor without a window.
set(FORBIDDEN_SYSTEM_session "imgui" "GLFW/" "epoxy/" "GL/")

set(violations "")
set(count 0)
foreach(layer session probe render audio widgets)
  file(GLOB sources LIST_DIRECTORIES false "${ROOT}/ui/${layer}/*.h" "${ROOT}/ui/${layer}/*.cpp")
  foreach(source ${sources})
    file(RELATIVE_PATH where ${ROOT} ${source})
    file(STRINGS ${source} lines REGEX "^[ \t]*#[ \t]*include[ \t]+[\"<]")
    foreach(line ${lines})
      math(EXPR count "${count} + 1")
      if(line MATCHES "\"((core|ui)/[^\"]*)\"")
        set(included ${CMAKE_MATCH_1})
        set(ok FALSE)
        foreach(prefix ${ALLOWED_${layer}})
          string(FIND "${included}" "${prefix}" at)
          if(at EQUAL 0)
            set(ok TRUE)
          endif()
        endforeach()
        if(NOT ok)
          string(APPEND violations "  ${where}: includes ${included}: ui/${layer} may include only "
                                   "${ALLOWED_${layer}}\n")
        endif()
      elseif(line MATCHES "<([^>]*)>")
        set(included ${CMAKE_MATCH_1})
        foreach(prefix ${FORBIDDEN_SYSTEM_${layer}})
          string(FIND "${included}" "${prefix}" at)
          if(at EQUAL 0)
            string(APPEND violations "  ${where}: includes <${included}>: ui/${layer} has no ImGui, GL or GLFW\n")
          endif()
        endforeach()
      endif()
    endforeach()
  endforeach()
endforeach()

if(violations)
  message(FATAL_ERROR "ui layering violated:\n${violations}")
endif()
message(STATUS "ui layering holds: ${count} includes checked")
