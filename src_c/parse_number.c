/* parse_number.c — the one number grammar of every text input: law keywords (and through
 * them the engines' pair_coeff and LIGGGHTS settings), the CLI's options and replay files. */
#include "capbridge.h"

#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

int cb_parse_number(const char *text, double *value)
{
    if (!text || !*text || !value) return 0;
    /* decimal notation only: no blanks, no hexadecimal, no "inf" or "nan" */
    if (text[strspn(text, "0123456789+-.eE")] != '\0') return 0;
    char *end = NULL;
    errno = 0;
    double v = strtod(text, &end);
    if (end == text || *end != '\0' || !isfinite(v)) return 0;
    /* out of double range: an overflow is caught above (inf); an underflow would pass a
     * nonzero value on as 0 or a subnormal without a word */
    if (errno == ERANGE) return 0;
    *value = v;
    return 1;
}
