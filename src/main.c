/* placeholder, replaced by the CLI */
#include "ricochet/ricochet.h"
int main(void) { return 0; }
