//! Scenario files as `impax compare FILE --json` and `impax simulate FILE --json` read them
//! (planar and `space = "3d"` bodies, mechanism files, simulation scenarios): every text is
//! either refused with exit 2 and one error line, or gives a document without a non-finite
//! number (`impax_cli::contract`).
#![no_main]

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    impax_fuzz::each_command_keeps_the_contract(
        data,
        "scenario",
        &[
            &["compare", "FILE", "--json"],
            &[
                "simulate",
                "FILE",
                "--json",
                "--until",
                "0.2",
                "--samples",
                "20",
            ],
        ],
    );
});
