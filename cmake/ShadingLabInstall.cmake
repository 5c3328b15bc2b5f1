# What `cmake --install` puts where, and the CMake package
# (find_package(ShadingLab) -> ShadingLab::GL, ShadingLab::CPU, ...).
# Included last from the top-level CMakeLists.txt.
include(CMakePackageConfigHelpers)

set(SHADINGLAB_INSTALL_CMAKEDIR "${CMAKE_INSTALL_LIBDIR}/cmake/ShadingLab")

# --- Programs and the explorer's desktop entry ------------------------------
install(TARGETS shadinglab RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR} COMPONENT Runtime)
if(SHADINGLAB_HAVE_QT)
  install(TARGETS shadinglab-gui RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR} COMPONENT Runtime)
  install(FILES ${PROJECT_SOURCE_DIR}/apps/gui/shadinglab-gui.desktop
    DESTINATION ${CMAKE_INSTALL_DATADIR}/applications COMPONENT Runtime)
  install(FILES ${PROJECT_SOURCE_DIR}/apps/gui/shadinglab-gui.svg
    DESTINATION ${CMAKE_INSTALL_DATADIR}/icons/hicolor/scalable/apps COMPONENT Runtime)
endif()
install(FILES ${PROJECT_SOURCE_DIR}/README.md ${PROJECT_SOURCE_DIR}/LICENSE
  DESTINATION ${CMAKE_INSTALL_DOCDIR} COMPONENT Runtime)

# --- Libraries and headers (static; the package carries their dependencies) -
# Each library's name in the package: ShadingLab::<name>, in one export set
# per package component: CPU (the model and the software renderer, no VTK),
# VTK (the mesh preparation step; the VTK modules, ShadingLab::RenderVTK,
# Mesh, CPUVTK, GL and VTK, are exported by vtk_module_build beside it) and
# IO (the mesh reader, VTK's IO modules).
set(_shadinglab_exported_CPU
  shadinglab_warnings Warnings
  shadinglab_compat Compat
  shadinglab_model Model
  shadinglab_render Render
  shadinglab_meshcore MeshCore
  shadinglab_cpu CPU)
set(_shadinglab_exported_VTK
  shadinglab_meshprep MeshPrep)
set(_shadinglab_exported_IO
  shadinglab_meshio MeshIO)
# The VTK modules each component's libraries link (the package finds only
# those of the components asked for: IOExodus brings HDF5, whose lookup in
# ParaView 5.11's VTK compiles C).
set(SHADINGLAB_PACKAGE_VTK_MODULES
  CommonCore CommonDataModel CommonExecutionModel CommonMath CommonTransforms
  FiltersCore FiltersGeneral RenderingCore RenderingOpenGL2)
set(SHADINGLAB_PACKAGE_IO_MODULES
  CommonCore CommonDataModel FiltersCore FiltersGeometry
  IOCore IOLegacy IOXML IOPLY IOGeometry IOExodus)
foreach(_component CPU VTK IO)
  set(_shadinglab_targets)
  set(_list ${_shadinglab_exported_${_component}})
  while(_list)
    list(POP_FRONT _list _target _name)
    set_target_properties(${_target} PROPERTIES EXPORT_NAME ${_name})
    list(APPEND _shadinglab_targets ${_target})
  endwhile()
  install(TARGETS ${_shadinglab_targets} EXPORT ShadingLab${_component}Targets
    ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT Development
    INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
  install(EXPORT ShadingLab${_component}Targets NAMESPACE ShadingLab::
    FILE ShadingLab${_component}Targets.cmake
    DESTINATION ${SHADINGLAB_INSTALL_CMAKEDIR} COMPONENT Development)
  # The build tree's copy (vtk_module_build exports the GL module from there too).
  export(EXPORT ShadingLab${_component}Targets NAMESPACE ShadingLab::
    FILE ${PROJECT_BINARY_DIR}/${SHADINGLAB_INSTALL_CMAKEDIR}/ShadingLab${_component}Targets.cmake)
endforeach()
# Namespaced headers (shadinglab/model, render, cpu, gl, Version.h) ...
foreach(_dir plugin/model/include plugin/render/include plugin/cpu/include plugin/gl/include)
  install(DIRECTORY ${PROJECT_SOURCE_DIR}/${_dir}/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}
    COMPONENT Development FILES_MATCHING PATTERN "*.h")
endforeach()
install(FILES ${PROJECT_BINARY_DIR}/plugin/model/include/shadinglab/Version.h
  DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/shadinglab COMPONENT Development)
# ... and the VTK-side and mesh headers, included by file name as VTK's are.
# (The VTK classes' headers are installed by vtk_module_build.)
file(GLOB _shadinglab_flat_headers
  ${PROJECT_SOURCE_DIR}/mesh/core/*.h ${PROJECT_SOURCE_DIR}/mesh/vtk/MeshArrays.h
  ${PROJECT_SOURCE_DIR}/plugin/render/vtk/PolyDataMesh.h ${PROJECT_SOURCE_DIR}/plugin/render/vtk/VtkCamera.h
  ${PROJECT_SOURCE_DIR}/plugin/render/vtk/VtkLights.h
  ${PROJECT_SOURCE_DIR}/mesh/io/MeshIO.h ${PROJECT_SOURCE_DIR}/mesh/io/MeshPrecheck.h
  ${PROJECT_SOURCE_DIR}/mesh/prep/*.h)
install(FILES ${_shadinglab_flat_headers}
  DESTINATION ${SHADINGLAB_INSTALL_FLAT_INCLUDEDIR} COMPONENT Development)

# --- ParaView's plugin list -------------------------------------------------
# Installed into ParaView's prefix (the Debian package), LoadDistributedPlugin
# and the plugin manager list ShadingLab without PV_PLUGIN_PATH. Two ways:
# - ParaView 5.11 (Debian 12) reads bin/paraview.conf beside its executables,
#   each line a plugin XML relative to that directory: ours is installed.
# - Debian 13 and unstable own that file (lib/<arch>/paraview-X.Y/paraview.conf)
#   and list in it /usr/share/paraview/plugins, a folder whose every plugin
#   ParaView registers: a link to ours is installed there.
if(SHADINGLAB_PARAVIEW_PLUGIN)
  set(_shadinglab_plugin_so
    "${CMAKE_INSTALL_LIBDIR}/${SHADINGLAB_PARAVIEW_PLUGIN_SUBDIR}/ShadingLab/ShadingLab.so")
  set(_shadinglab_debian_conf
    "/usr/lib/${CMAKE_LIBRARY_ARCHITECTURE}/paraview-${ParaView_VERSION_MAJOR}.${ParaView_VERSION_MINOR}/paraview.conf")
  set(_shadinglab_plugin_folder "")
  if(EXISTS "${_shadinglab_debian_conf}")
    file(STRINGS "${_shadinglab_debian_conf}" _shadinglab_conf_lines)
    foreach(_line IN LISTS _shadinglab_conf_lines)
      if(_line MATCHES "^/usr/share/")
        set(_shadinglab_plugin_folder "${_line}")
      endif()
    endforeach()
  endif()
  if(_shadinglab_plugin_folder)
    string(REGEX REPLACE "^/usr/" "" _shadinglab_plugin_folder "${_shadinglab_plugin_folder}")
    file(RELATIVE_PATH _shadinglab_so_from_folder "/prefix/${_shadinglab_plugin_folder}"
      "/prefix/${_shadinglab_plugin_so}")
    file(MAKE_DIRECTORY "${PROJECT_BINARY_DIR}/plugin-link")
    file(CREATE_LINK "${_shadinglab_so_from_folder}" "${PROJECT_BINARY_DIR}/plugin-link/ShadingLab.so"
      SYMBOLIC)
    install(FILES "${PROJECT_BINARY_DIR}/plugin-link/ShadingLab.so"
      DESTINATION "${_shadinglab_plugin_folder}" COMPONENT Runtime)
  else()
    file(RELATIVE_PATH _shadinglab_xml_from_bin "/prefix/${CMAKE_INSTALL_BINDIR}"
      "/prefix/${CMAKE_INSTALL_LIBDIR}/${SHADINGLAB_PARAVIEW_PLUGIN_SUBDIR}/ShadingLab.plugins.xml")
    file(WRITE ${PROJECT_BINARY_DIR}/paraview.conf "${_shadinglab_xml_from_bin}\n")
    install(FILES ${PROJECT_BINARY_DIR}/paraview.conf DESTINATION ${CMAKE_INSTALL_BINDIR}
      COMPONENT Runtime)
  endif()
endif()

# --- The package configuration ----------------------------------------------
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/ShadingLabConfig.cmake.in
  ${PROJECT_BINARY_DIR}/ShadingLabConfig.cmake
  INSTALL_DESTINATION ${SHADINGLAB_INSTALL_CMAKEDIR})
write_basic_package_version_file(${PROJECT_BINARY_DIR}/ShadingLabConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/ShadingLabConfig.cmake
  ${PROJECT_BINARY_DIR}/ShadingLabConfigVersion.cmake
  DESTINATION ${SHADINGLAB_INSTALL_CMAKEDIR} COMPONENT Development)

# --- Debian packages: cpack -G DEB -------------------------------------------
# shadinglab (programs, explorer, ParaView plugin, the Python package in
# /usr/lib/python3/dist-packages; dependencies from dpkg-shlibdeps) and shadinglab-dev (static libraries, headers, the CMake
# package; it depends on what ShadingLabConfig.cmake finds).
set(CPACK_PACKAGE_NAME shadinglab)
set(CPACK_PACKAGE_VENDOR "ShadingLab")
set(CPACK_PACKAGE_CONTACT "ShadingLab developers <shadinglab@localhost>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY
  "Flat, Gouraud, Phong and fast Phong shading for VTK and ParaView, with a CPU reference renderer")
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_COMPONENTS_ALL Runtime Development)
set(CPACK_DEB_COMPONENT_INSTALL ON)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_RUNTIME_PACKAGE_NAME shadinglab)
set(CPACK_DEBIAN_RUNTIME_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_RUNTIME_PACKAGE_SUGGESTS paraview)
set(CPACK_DEBIAN_DEVELOPMENT_PACKAGE_NAME shadinglab-dev)
set(CPACK_DEBIAN_DEVELOPMENT_PACKAGE_SECTION libdevel)
set(CPACK_DEBIAN_DEVELOPMENT_PACKAGE_DEPENDS
  "shadinglab (= ${PROJECT_VERSION}), paraview-dev, libopenmesh-dev, libosd-dev, libx11-dev")
set(CPACK_RESOURCE_FILE_LICENSE ${PROJECT_SOURCE_DIR}/LICENSE)
include(CPack)
