# SPDX-License-Identifier: Apache-2.0

module Kit {

    @ A build without F´'s parameter database (CONFIG_KIT_SERVICE_PARAMS=n):
    @ answers every parameter read "not in the database", so each component
    @ takes its parameter's default, as F´'s generated code does for a
    @ value the database lacks. F´ asserts that a component with parameters
    @ has its read port connected. There is no save port: a parameter's
    @ _PRM_SAVE command then fails with EXECUTION_ERROR.
    passive component ParamDefaults {

        @ A parameter's read
        sync input port getPrm: Fw.PrmGet
    }
}
