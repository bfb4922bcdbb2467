# `cmake --install`: the libraries as the namespaced package scalcal (find_package(scalcal) gives
# scalcal::numeric, scalcal::symbolic, scalcal::plots and the numeric parts scalcal::model, ...),
# their headers under include/scalcal, the CLI, the paper's tables, and scalcal-numeric.pc.
include(CMakePackageConfigHelpers)

get_property(SCALCAL_EXPORTED GLOBAL PROPERTY SCALCAL_EXPORTED)
install(TARGETS ${SCALCAL_EXPORTED} EXPORT scalcalTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR})
set(SCALCAL_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/scalcal)
install(EXPORT scalcalTargets NAMESPACE scalcal:: DESTINATION ${SCALCAL_CMAKE_DIR})

set(SCALCAL_HEADER_FOLDERS numeric)
if(SCALCAL_WITH_GINAC)
  list(APPEND SCALCAL_HEADER_FOLDERS symbolic)
endif()
if(SCALCAL_BUILD_PLOTS)
  list(APPEND SCALCAL_HEADER_FOLDERS plots)
endif()
foreach(folder ${SCALCAL_HEADER_FOLDERS})
  install(DIRECTORY ${PROJECT_SOURCE_DIR}/${folder} DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/scalcal
          FILES_MATCHING PATTERN "*.hpp")
endforeach()
install(DIRECTORY ${PROJECT_SOURCE_DIR}/data/ DESTINATION ${CMAKE_INSTALL_DATADIR}/scalcal/data)

configure_package_config_file(${CMAKE_CURRENT_LIST_DIR}/scalcalConfig.cmake.in
                              ${PROJECT_BINARY_DIR}/scalcalConfig.cmake INSTALL_DESTINATION ${SCALCAL_CMAKE_DIR})
write_basic_package_version_file(${PROJECT_BINARY_DIR}/scalcalConfigVersion.cmake COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/scalcalConfig.cmake ${PROJECT_BINARY_DIR}/scalcalConfigVersion.cmake
        DESTINATION ${SCALCAL_CMAKE_DIR})

# pkg-config for the numeric part: static archives, so every library they need is listed, dependents
# first (scalcal_numeric links its parts dependencies first).
set(SCALCAL_PC_LIBS "")
get_target_property(SCALCAL_NUMERIC_PARTS scalcal_numeric INTERFACE_LINK_LIBRARIES)
list(REVERSE SCALCAL_NUMERIC_PARTS)
foreach(part ${SCALCAL_NUMERIC_PARTS})
  get_target_property(type ${part} TYPE)
  if(type STREQUAL "STATIC_LIBRARY")
    string(APPEND SCALCAL_PC_LIBS " -l${part}")
  endif()
endforeach()
configure_file(${CMAKE_CURRENT_LIST_DIR}/scalcal-numeric.pc.in ${PROJECT_BINARY_DIR}/scalcal-numeric.pc @ONLY)
install(FILES ${PROJECT_BINARY_DIR}/scalcal-numeric.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig)
