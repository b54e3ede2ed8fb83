/* Compiled with -std=c99 -Wall -Wextra -pedantic -Werror: the public header
 * must compile alone as strict C99 (house rule 6). */
#include "eoir/eoir.h"

int eoir_header_c99_check(void);
int eoir_header_c99_check(void) { return (int)sizeof(eoir_api_v1); }
