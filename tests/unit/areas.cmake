# The core's unit suites, one Unity program per area (test_<area>.c). The
# one list read by tests/unit (host programs), tests/target (firmware
# images), run_option_matrix.sh and mutation_check.py, so a new suite runs
# everywhere at once.
set(DARAN_UNIT_AREAS
  framing
  checksum_and_words
  numbers_in_fields
  commands
  errors
  properties
  addressing
  states_and_queries
  api
  extensions
  can
  protocol
)
