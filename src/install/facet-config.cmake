# facet-config.cmake - `find_package(facet CONFIG)`; installed by `make
# install` (a copy of src/install/facet-config.cmake) into PREFIX/lib/cmake/facet/.
# Imported targets:
#   facet::facet         libfacet.so (the f32 kernels with their runtime
#                        dispatch, the fixed-point kernels, the oracle)
#   facet::facet_static  libfacet.a, with libm (only the oracle needs it)
# both with PREFIX/include on the include path.  Relocatable: the paths are
# taken from where this file is, so a copied or DESTDIR-staged tree works.
# facet_VERSION comes from facet-config-version.cmake.
get_filename_component(_facet_prefix "${CMAKE_CURRENT_LIST_DIR}/../../.." ABSOLUTE)
if(NOT TARGET facet::facet)
    add_library(facet::facet SHARED IMPORTED)
    set_target_properties(facet::facet PROPERTIES
        IMPORTED_LOCATION "${_facet_prefix}/lib/libfacet.so.0"
        IMPORTED_SONAME "libfacet.so.0"
        INTERFACE_INCLUDE_DIRECTORIES "${_facet_prefix}/include")
endif()
if(NOT TARGET facet::facet_static)
    add_library(facet::facet_static STATIC IMPORTED)
    set_target_properties(facet::facet_static PROPERTIES
        IMPORTED_LOCATION "${_facet_prefix}/lib/libfacet.a"
        IMPORTED_LINK_INTERFACE_LANGUAGES "C"
        INTERFACE_INCLUDE_DIRECTORIES "${_facet_prefix}/include"
        INTERFACE_LINK_LIBRARIES "m")
endif()
unset(_facet_prefix)
