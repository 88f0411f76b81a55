/* The options of the builds that update their firmware over the link: the
 * update module on (daran_update.h). */
#ifndef DARAN_UPDATE_OPTIONS_H
#define DARAN_UPDATE_OPTIONS_H

#define DARAN_ENABLE_UPDATE 1

#endif /* DARAN_UPDATE_OPTIONS_H */
