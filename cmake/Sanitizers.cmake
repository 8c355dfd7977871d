# AddressSanitizer + UndefinedBehaviorSanitizer for every target of the build when asked for.
if(CGAL_POLICIES_SANITIZE)
  add_compile_options(-fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=all)
  add_link_options(-fsanitize=address,undefined)
endif()
