/* status.c — status codes as sentences. */
#include "capbridge.h"

const char *cb_status_message(cb_status status)
{
    switch (status) {
    case CB_OK: return "ok";
    case CB_ERR_NULL: return "a required pointer argument is NULL";
    case CB_ERR_NOT_FINITE: return "an input is NaN or infinite";
    case CB_ERR_NEGATIVE: return "a radius, volume or surface tension is not positive";
    case CB_ERR_RANGE: return "an input lies outside the accepted range";
    case CB_ERR_UNKNOWN_LAW: return "unknown law";
    case CB_ERR_UNKNOWN_KEYWORD: return "unknown keyword or keyword value";
    case CB_ERR_OUT_OF_VALIDITY: return "outside the law's stated validity range (validity strict)";
    case CB_ERR_NO_BRIDGE: return "no bridge of this volume exists at this gap";
    case CB_ERR_NO_CONVERGENCE: return "the exact Laplace-Young solver did not converge";
    case CB_ERR_NO_MEMORY: return "out of memory";
    case CB_ERR_LIQUID: return "liquid bookkeeping would lose or create liquid";
    case CB_ERR_BRIDGE_STATE:
        return "the stored bridge state is not a valid bridge (a corrupted pair history, or "
               "one written by another build, e.g. in a restart file)";
    }
    return "unknown status";
}
