/* MoorDynAPI.h: the definitions shared by the MoorDyn-compatible C API of tangle (error codes, log levels,
 * the export macro). Names and values are MoorDyn v2.7.1's, so that a host program written against
 * MoorDyn's headers compiles unchanged against these and links against libtangle_moordyn instead.
 * What tangle implements, and what it does not: docs/moordyn.md, "C API and Python coupling".
 * Valid C99 and C++. */

#ifndef TANGLE_MOORDYN_API_H
#define TANGLE_MOORDYN_API_H

/* Defined by these headers (and not by MoorDyn's), for a host that wants to know which library it has. */
#define TANGLE_MOORDYN_API 1

/* DECLDIR marks the functions the library exports. The library is built with hidden visibility, so only
 * the functions declared with DECLDIR are visible to a host. CMake defines tangle_moordyn_EXPORTS while it
 * builds the library. */
#if defined(_WIN32)
#if defined(tangle_moordyn_EXPORTS)
#define DECLDIR __declspec(dllexport)
#else
#define DECLDIR __declspec(dllimport)
#endif
#elif defined(__GNUC__) || defined(__clang__)
#define DECLDIR __attribute__((visibility("default")))
#else
#define DECLDIR
#endif

/* Marks the functions MoorDyn itself marks as deprecated. */
#ifndef DEPRECATED
#if defined(_MSC_VER)
#define DEPRECATED __declspec(deprecated)
#elif defined(__GNUC__) || defined(__clang__)
#define DEPRECATED __attribute__((__deprecated__))
#else
#define DEPRECATED
#endif
#endif

/* Message levels (MoorDyn_SetVerbosity, MoorDyn_SetLogLevel, MoorDyn_Log): a message is shown when its
 * level is at least the threshold. */
#define MOORDYN_DBG_LEVEL 0    /* debugging */
#define MOORDYN_MSG_LEVEL 1    /* information */
#define MOORDYN_WRN_LEVEL 2    /* warnings */
#define MOORDYN_ERR_LEVEL 3    /* errors */
#define MOORDYN_NO_OUTPUT 4096 /* a threshold no message reaches: nothing is shown */

/* What the functions return. tangle's own exceptions are turned into these codes at the C boundary, with
 * their message printed on stderr (docs/moordyn.md gives the mapping). */
#define MOORDYN_SUCCESS 0
#define MOORDYN_INVALID_INPUT_FILE -1  /* the input file cannot be read */
#define MOORDYN_INVALID_OUTPUT_FILE -2 /* an output file cannot be written */
#define MOORDYN_INVALID_INPUT -3       /* the input is invalid (tangle::InputError) */
#define MOORDYN_NAN_ERROR -4           /* the model cannot be advanced (tangle::ConvergenceError) */
#define MOORDYN_MEM_ERROR -5           /* out of memory */
#define MOORDYN_INVALID_VALUE -6       /* a NULL or closed handle, an index out of range, bad call order */
#define MOORDYN_NON_IMPLEMENTED -7     /* a function tangle does not implement */
#define MOORDYN_UNHANDLED_ERROR -255   /* any other error */

#endif /* TANGLE_MOORDYN_API_H */
