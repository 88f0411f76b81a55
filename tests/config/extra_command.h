/* An options header that adds one command of the build's own to the
 * protocol table (include/daran_protocol.h, DARAN_EXTRA_COMMANDS): `ec id
 * value`, a query that answers its value, with no CAN form. What adding it
 * took is this row and its handler (tests/bridge/test_extra_command.c);
 * the drive, `h`, the bridge and the client know it from the row alone. */
#ifndef EXTRA_COMMAND_H
#define EXTRA_COMMAND_H

#define DARAN_EXTRA_COMMANDS(X)                                                           \
    X(EC, 'e', 'c', ALWAYS, QUERY, ONE_LINE, RETRY, test_echo, NONE, NONE, "value",     \
      REQ_ID, REQ_F32, NONE, NONE, NONE, NONE)

#endif /* EXTRA_COMMAND_H */
