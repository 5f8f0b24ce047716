# fosssim_options(target): the project's per-target compile settings (warnings, floating point,
# sanitizers). Nothing here is global: every target of the project calls this on itself.
option(FOSSSIM_WERROR "Treat compiler warnings as errors (on in CI: .ci/run)" OFF)

function(fosssim_options target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow -Wnon-virtual-dtor)
  if(FOSSSIM_WERROR)
    target_compile_options(${target} PRIVATE -Werror)
    # gcc's maybe-uninitialized depends on how far the optimiser inlines, and in the sanitizer
    # build (-O1 with ASan) it fires inside libstdc++'s own <regex> and <functional> (gcc 12):
    # it stays a warning, never an error.
    if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
      target_compile_options(${target} PRIVATE -Wno-error=maybe-uninitialized)
    endif()
  endif()
  # Bit-for-bit results (--compat against the course's files, identical results for every thread
  # count, trajectories that do not change with the compiler) need every a*b+c rounded twice, as
  # written. Compilers may otherwise fuse it into one fused multiply-add wherever the target has
  # FMA (clang contracts by default within an expression; gcc at -march=native or on aarch64),
  # which changes the last bits of every polynomial coefficient. Box2D builds with the same flag
  # for the same reason (cross-platform determinism).
  target_compile_options(${target} PRIVATE -ffp-contract=off)
  if(FOSSSIM_SANITIZE)
    target_compile_options(${target} PRIVATE -fsanitize=address,undefined -fno-omit-frame-pointer
                                             -fno-sanitize-recover=undefined)
    target_link_options(${target} PRIVATE -fsanitize=address,undefined)
  endif()
endfunction()
