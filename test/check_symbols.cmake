# SPDX-License-Identifier: BSD-3-Clause
# test/check_symbols.cmake - the library may reference nothing outside an allow-list.
#
#   cmake -DNM=<nm> -DLIB=<libmtt.a> -P check_symbols.cmake
#
# Every symbol that libmtt.a leaves undefined (referenced by one object and
# defined by none) must be a math function, a mem*/str* function or a
# compiler helper.  So malloc/calloc/realloc/free, printf and the rest of
# stdio, clocks, abort/exit and hidden globals such as stderr all fail.
cmake_minimum_required(VERSION 3.25)

if(NOT NM OR NOT LIB)
  message(FATAL_ERROR "usage: cmake -DNM=<nm> -DLIB=<libmtt.a> -P check_symbols.cmake")
endif()
if(NOT EXISTS "${LIB}")
  message(FATAL_ERROR "library ${LIB} does not exist (build first)")
endif()

# C99 <math.h> functions, each in its double, float and long double spelling.
set(_math_base
  acos asin atan atan2 cos sin tan acosh asinh atanh cosh sinh tanh
  exp exp2 expm1 frexp ilogb ldexp log log10 log1p log2 logb modf scalbn scalbln
  cbrt fabs hypot pow sqrt erf erfc lgamma tgamma ceil floor nearbyint rint lrint
  llrint round lround llround trunc fmod remainder remquo copysign nan nextafter
  nexttoward fdim fmax fmin fma)
set(_allowed "")
foreach(_f IN LISTS _math_base)
  list(APPEND _allowed ${_f} ${_f}f ${_f}l)
endforeach()
list(APPEND _allowed
  # GNU sincos: GCC fuses a sin and a cos of the same argument into it (glibc, newlib)
  sincos sincosf sincosl
  # glibc's out-of-line versions of classification macros and old -ffast-math entry points
  __fpclassify __fpclassifyf __fpclassifyl __isnan __isnanf __isnanl __isinf __isinff
  __isinfl __finite __finitef __finitel __signbit __signbitf __signbitl
  __sqrt_finite __sqrtf_finite __exp_finite __expf_finite __log_finite __logf_finite
  __pow_finite __powf_finite
  # memory and string functions (no allocation, no I/O); the compiler may emit mem* by itself
  memset memcpy memmove memcmp memchr strcmp strncmp strlen strchr
  __memset_chk __memcpy_chk __memmove_chk
  # stack protector and PIC helpers
  __stack_chk_fail __stack_chk_fail_local __stack_chk_guard _GLOBAL_OFFSET_TABLE_
  __tls_get_addr _DYNAMIC)
# libgcc / compiler-rt arithmetic helpers (soft-float and wide integer ops, ARM EABI).
set(_helper_regex
  "^__(aeabi_[a-z0-9_]+|(u?(div|mod)|mul|neg|ashl|ashr|lshr|clz|ctz|popcount|parity|bswap|ffs|cmp|ucmp)[dst]i[0-9]|(add|sub|mul|div|neg|pow[i]?|extend[a-z0-9]*|trunc[a-z0-9]*|fix(uns)?[a-z0-9]*|float(un)?[a-z0-9]*|eq|ne|lt|le|gt|ge|unord|cmp)[sdtx]f[0-9][a-z0-9]*)$")

# Names that are certainly wrong, to say why.
set(_forbidden_regex
  "^(_*(malloc|calloc|realloc|free|aligned_alloc|posix_memalign|memalign|valloc|alloca|strdup|strndup)|.*printf.*|.*scanf.*|puts|putchar|putc|fputc|fputs|fopen|fopen64|fdopen|freopen|fclose|fflush|fread|fwrite|fgetc|fgets|getc|getchar|gets|ungetc|perror|fseek|ftell|rewind|setvbuf|setbuf|remove|rename|tmpfile|tmpnam|_IO_.*|stdin|stdout|stderr|__(fprintf|printf|sprintf|snprintf|vfprintf|vprintf|vsprintf|vsnprintf)_chk|abort|exit|_exit|atexit|time|clock|clock_gettime|gettimeofday|rand|srand|getenv|system|signal|raise|setjmp|longjmp|__assert_fail|__assert|_assert)$")

execute_process(COMMAND "${NM}" -A -g "${LIB}"
  OUTPUT_VARIABLE _out ERROR_VARIABLE _err RESULT_VARIABLE _rc)
if(NOT _rc EQUAL 0)
  message(FATAL_ERROR "${NM} -A -g ${LIB} failed (${_rc}): ${_err}")
endif()

# Lines: "<archive>:<object>: [address] <type> <name>"
string(REPLACE "\n" ";" _lines "${_out}")
set(_defined "")
set(_undef "")
foreach(_l IN LISTS _lines)
  if(_l MATCHES "^(.*): +U ([^ ]+)$")
    list(APPEND _undef "${CMAKE_MATCH_2}|${CMAKE_MATCH_1}")
  elseif(_l MATCHES "^(.*): *[0-9a-fA-F]* +[A-TV-Za-z] ([^ ]+)$")
    list(APPEND _defined "${CMAKE_MATCH_2}")
  endif()
endforeach()
list(REMOVE_DUPLICATES _defined)

set(_bad "")
set(_external "")
foreach(_e IN LISTS _undef)
  string(REPLACE "|" ";" _pair "${_e}")
  list(GET _pair 0 _sym)
  list(GET _pair 1 _where)
  string(REGEX REPLACE "@.*$" "" _sym "${_sym}")  # versioned names: memcpy@GLIBC_2.14
  if(_sym IN_LIST _defined)
    continue()
  endif()
  list(APPEND _external "${_sym}")
  if(_sym IN_LIST _allowed OR _sym MATCHES "${_helper_regex}")
    continue()
  endif()
  string(REGEX REPLACE "^.*:" "" _obj "${_where}")
  get_filename_component(_obj "${_obj}" NAME)
  if(_sym MATCHES "${_forbidden_regex}")
    list(APPEND _bad "  ${_sym}    (${_obj}: allocation, I/O or process/clock access)")
  else()
    list(APPEND _bad "  ${_sym}    (${_obj}: not on the allow-list in test/check_symbols.cmake)")
  endif()
endforeach()
list(REMOVE_DUPLICATES _external)
list(SORT _external)
list(REMOVE_DUPLICATES _bad)

string(REPLACE ";" " " _ext_txt "${_external}")
message("external symbols of ${LIB}: ${_ext_txt}")
if(_bad)
  list(LENGTH _bad _n)
  string(REPLACE ";" "\n" _bad_txt "${_bad}")
  message("FAIL: libmtt references ${_n} forbidden symbol(s):\n${_bad_txt}")
  message(FATAL_ERROR "symbol check failed")
endif()
message("OK: no allocation, no stdio, nothing outside the allow-list")
