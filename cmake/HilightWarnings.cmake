# hilight_warnings(target): the warning set every hilight target builds with.
function(hilight_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow
                         -Wno-missing-field-initializers)
endfunction()
