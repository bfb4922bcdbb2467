# CPack's pre-build step (package.cmake): in the staged /usr tree, the Python package moves from
# lib/pythonX.Y/site-packages (cmake --install's default) to lib/python3/dist-packages, Debian's path.
file(GLOB_RECURSE inits "${CPACK_TEMPORARY_INSTALL_DIRECTORY}/__init__.py")
list(FILTER inits INCLUDE REGEX "/site-packages/scalcal/__init__.py$")
foreach(init ${inits})
  get_filename_component(package "${init}" DIRECTORY)
  get_filename_component(site "${package}" DIRECTORY)
  get_filename_component(lib "${site}" DIRECTORY)
  get_filename_component(lib "${lib}" DIRECTORY)
  file(MAKE_DIRECTORY "${lib}/python3/dist-packages")
  file(RENAME "${package}" "${lib}/python3/dist-packages/scalcal")
  file(REMOVE_RECURSE "${site}")
  get_filename_component(version_dir "${site}" DIRECTORY)  # lib/pythonX.Y, now empty unless others use it
  file(GLOB left "${version_dir}/*")
  if(NOT left)
    file(REMOVE_RECURSE "${version_dir}")
  endif()
endforeach()
