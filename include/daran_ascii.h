/** @file daran_ascii.h
 * daran-ascii: the Daran servo drive ASCII protocol as an embeddable,
 * zero-allocation C library. Include this one header. */
#ifndef DARAN_ASCII_H
#define DARAN_ASCII_H

#include "daran_can.h"
#include "daran_config.h"
#include "daran_drive.h"
#include "daran_hal.h"
#include "daran_port.h"
#include "daran_properties.h"
#include "daran_protocol.h"
#include "daran_result.h"
#include "daran_update.h"
#include "daran_version.h"

#endif /* DARAN_ASCII_H */
