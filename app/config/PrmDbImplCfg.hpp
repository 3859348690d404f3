// SPDX-License-Identifier: Apache-2.0
// Parameter database: one entry per parameter of the dictionary. Svc.PrmDb
// keeps two copies of its table (the active one and the staging one a file
// load fills), each entry a parameter buffer with its id: at F´'s 25
// entries, 2584 B of RAM in the kit's qemu_cortex_m3 build, for the
// reference deployment's 2 parameters. The deployment's count is a Kconfig
// setting (CONFIG_KIT_DEPLOYMENT_PARAMETERS, app/Kconfig: the reference's by
// default, another deployment's in its deployment.conf); a table smaller
// than the build's dictionary fails the build (app/src/DictionaryChecks.cpp):
// PrmDb would refuse a parameter past it at run time (PrmIdNotFound,
// PrmDbFull).
#ifndef PRMDB_PRMDBLIMPLCFG_HPP_
#define PRMDB_PRMDBLIMPLCFG_HPP_

namespace {

enum {
    PRMDB_NUM_DB_ENTRIES = CONFIG_KIT_DEPLOYMENT_PARAMETERS,  //!< entries in each of the database's two tables
    PRMDB_ENTRY_DELIMITER = 0xA5  //!< F´'s: the byte before each parameter in the file, as the ground writes it
};

}

#endif
