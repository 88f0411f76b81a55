/* The conformance suite's program: runs the protocol contract against the
 * adopter's HAL (daran_test_port(), daran_test_port.h) and reports each
 * failed requirement with the lines sent, the replies and the HAL calls.
 * Exit status 0 when every check passed, 1 when one failed, 2 when the
 * test port itself is unusable. docs/conformance.md says what each
 * requirement checks. */
#include <stdio.h>
#include <string.h>

#include "conformance.h"

static int usage(const char *program, int status)
{
    printf("usage: %s [--verbose] [--transcripts] [--list]\n"
           "  runs the daran-ascii conformance suite against this program's test port\n"
           "  --verbose      print every check, and the transcript of every failure\n"
           "  --transcripts  print every check with its transcript (lines, replies, HAL calls)\n"
           "  --list         print the requirements and exit\n",
           program);
    return status;
}

/* What the program needs of the test port before anything can run. */
static const char *port_problem(const daran_test_port_t *port)
{
    if (port == NULL) {
        return "daran_test_port() returned NULL";
    }
    if (port->hal == NULL || port->hal->get == NULL || port->hal->set == NULL ||
        port->hal->move == NULL || port->hal->action == NULL) {
        return "the test port's hal (or one of its four functions) is NULL";
    }
    if (port->reset == NULL) {
        return "the test port has no reset()";
    }
    if (port->command_count > 0u && port->commands == NULL) {
        return "the test port gives a command count but no commands";
    }
    if ((port->hal->can_send == NULL) != (port->hal->now_ms == NULL)) {
        return "the test port's hal gives one of can_send() and now_ms() without the other";
    }
    if (port->hal->can_send == NULL && port->can_deliver != NULL) {
        return "the test port gives can_deliver but its hal no can_send()";
    }
    return NULL;
}

int main(int argc, char **argv)
{
    bool verbose = false;
    bool transcripts = false;
    for (int i = 1; i < argc; i++) {
        if (strcmp(argv[i], "--verbose") == 0) {
            verbose = true;
        } else if (strcmp(argv[i], "--transcripts") == 0) {
            transcripts = true;
        } else if (strcmp(argv[i], "--list") == 0) {
            conf_list_requirements();
            return 0;
        } else {
            return usage(argv[0], strcmp(argv[i], "--help") == 0 ? 0 : 2);
        }
    }
    const daran_test_port_t *port = daran_test_port();
    const char *problem = port_problem(port);
    if (problem != NULL) {
        printf("FATAL %s (see daran_test_port.h)\n0 passed, 1 failed\n", problem);
        return 2;
    }
    printf("daran-ascii %s conformance suite, port: %s\n", daran_version(),
           port->name != NULL ? port->name : "(unnamed)");
    printf("build: DARAN_LINE_MAX %d, DARAN_REPLY_MAX %d, DARAN_MOTOR_ID_MAX %d, help %s, "
           "multi-motor %s, %d property ids, CAN %s\n\n",
           DARAN_LINE_MAX, DARAN_REPLY_MAX, DARAN_MOTOR_ID_MAX, DARAN_ENABLE_HELP ? "on" : "off",
           DARAN_ENABLE_MULTI_MOTOR ? "on" : "off", (int)DARAN_PROP_COUNT,
           !DARAN_ENABLE_CAN ? "compiled out"
           : port->hal->can_send == NULL ? "not given by the test port"
           : port->can_deliver == NULL ? "on (no can_deliver: no filter)"
                                       : "on");

    conf_harness_init(port, verbose, transcripts);
    conf_model_init();
    if (!conf_check_factory_state()) {
        /* every later check starts from that state: they would only repeat this failure */
        printf("\nstopped: the checks after C1 start from the factory state reset() must give\n");
        return conf_report() == 0 ? 1 : 1;
    }
    conf_check_properties();
    conf_check_commands();
    conf_check_persistence();
    conf_check_bad_input();
    conf_check_can();
    return conf_report();
}
