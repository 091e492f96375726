# gdnav_idl_library(<target> <idl files...> [GEN_REPLACE <text> <replacement>])
# Runs fastddsgen at build time (never committed) into ${CMAKE_CURRENT_BINARY_DIR}/<target>_gen and builds a
# static library of the generated types. `-replace` is needed: without it fastddsgen silently keeps stale files.
# GEN_REPLACE: fastddsgen reads a copy of each file with <text> replaced (e.g. a member name fastddsgen refuses),
# while the IDL text compiled in for recordings (msg::idl_text::<base>()) stays the file as written. Only for changes
# that leave the CDR encoding alone (member names are not on the wire).
function(gdnav_idl_library target)
  cmake_parse_arguments(ARG "" "" "GEN_REPLACE" ${ARGN})
  set(outdir ${CMAKE_CURRENT_BINARY_DIR}/${target}_gen)
  file(MAKE_DIRECTORY ${outdir})
  set(sources)
  foreach(idl ${ARG_UNPARSED_ARGUMENTS})
    get_filename_component(abs ${idl} ABSOLUTE)
    get_filename_component(base ${idl} NAME_WE)
    get_filename_component(name ${idl} NAME)
    set(gen_input ${abs})
    if(ARG_GEN_REPLACE)
      file(READ ${abs} _text)
      list(GET ARG_GEN_REPLACE 0 _from)
      list(GET ARG_GEN_REPLACE 1 _to)
      string(REPLACE "${_from}" "${_to}" _text "${_text}")
      set(gen_input ${outdir}/fastddsgen_input/${name})
      file(WRITE ${gen_input}.tmp "${_text}")
      configure_file(${gen_input}.tmp ${gen_input} COPYONLY)
    endif()
    set(gen ${outdir}/${base}.cxx ${outdir}/${base}.h ${outdir}/${base}PubSubTypes.cxx ${outdir}/${base}PubSubTypes.h)
    # fastddsgen's temporary files go to a folder of this library's own (-t): in the shared default temporary
    # folder, two builds generating the same IDL at once overwrite each other's files and fastddsgen can end without
    # writing some outputs; the check after it (sha256sum fails on a missing file) stops the build at this step.
    add_custom_command(
      OUTPUT ${gen}
      COMMAND ${CMAKE_COMMAND} -E make_directory ${outdir}/tmp_${base}
      COMMAND ${FASTDDSGEN} -replace -t ${outdir}/tmp_${base} -d ${outdir} ${gen_input}
      COMMAND ${CMAKE_COMMAND} -E sha256sum ${gen}
      DEPENDS ${abs}
      COMMENT "fastddsgen ${base}.idl"
      VERBATIM)
    list(APPEND sources ${outdir}/${base}.cxx ${outdir}/${base}PubSubTypes.cxx)
    # The IDL text itself, for self-describing recordings (MCAP schemas, omgidl): std::string_view
    # gdnav::msg::idl_text::<base>() in <base>IdlText.cxx (declared in idl/msgs/idl_text.hpp), regenerated when the
    # IDL changes (configure-time dependency).
    set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${abs})
    file(READ ${abs} _hex HEX)
    string(REGEX REPLACE "([0-9a-f][0-9a-f])" "0x\\1," _hex "${_hex}")
    file(WRITE ${outdir}/${base}IdlText.cxx.tmp
      "// Generated from ${abs} by cmake/GdnavIdl.cmake: the IDL text (a byte array: no string-length limit).\n"
      "#include <string_view>\nnamespace gdnav::msg::idl_text {\n"
      "namespace { const unsigned char k_${base}[] = {${_hex}}; }\n"
      "std::string_view ${base}() { return {reinterpret_cast<const char*>(k_${base}), sizeof(k_${base})}; }\n}\n")
    configure_file(${outdir}/${base}IdlText.cxx.tmp ${outdir}/${base}IdlText.cxx COPYONLY)
    list(APPEND sources ${outdir}/${base}IdlText.cxx)
  endforeach()
  add_library(${target} STATIC ${sources})
  target_include_directories(${target} SYSTEM PUBLIC $<BUILD_INTERFACE:${outdir}> $<INSTALL_INTERFACE:include/gdnav>)
  set_property(TARGET ${target} PROPERTY GDNAV_GENERATED_DIR ${outdir})
  target_link_libraries(${target} PUBLIC fastcdr fastrtps)
  set_target_properties(${target} PROPERTIES POSITION_INDEPENDENT_CODE ON)
endfunction()
