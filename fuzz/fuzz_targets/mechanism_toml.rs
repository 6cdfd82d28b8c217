//! Mechanism files (`mechanism = "double-pendulum"` and the built-ins' parameters) as
//! `impax compare`, `impax audit` and `impax conserved` read them: exit 2 with one error
//! line, or a document without a non-finite number (`impax_cli::contract`).
#![no_main]

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    impax_fuzz::each_command_keeps_the_contract(
        data,
        "mechanism",
        &[
            &["compare", "FILE", "--json"],
            &["audit", "FILE", "--json"],
            &[
                "conserved",
                "FILE",
                "--json",
                "--duration",
                "0.05",
                "--samples",
                "5",
            ],
        ],
    );
});
