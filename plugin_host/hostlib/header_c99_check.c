/* eoir_host.h compiles alone as C99 (-Wall -Wextra -pedantic -Werror). */
#include "eoir_host.h"

uint32_t eoir_host_header_check(void);
uint32_t eoir_host_header_check(void) { return EOIR_HOST_VERSION; }
