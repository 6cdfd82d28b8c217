//! What the file-reading fuzz targets share: write the input to a temporary file and hold
//! every command run on it to the command line's contract (`impax_cli::contract`).

use std::io::Write;

/// Write `data` to a temporary `.toml` file named after `name`, run each of `commands` on it
/// (the file's path replaces `FILE`) and panic on the first breach of the contract.
pub fn each_command_keeps_the_contract(data: &[u8], name: &str, commands: &[&[&str]]) {
    let path = std::env::temp_dir().join(format!("impax-fuzz-{name}-{}.toml", std::process::id()));
    let mut file = std::fs::File::create(&path).expect("temporary file");
    file.write_all(data).expect("temporary file");
    drop(file);
    let p = path.to_str().expect("UTF-8 path");
    for command in commands {
        let args: Vec<&str> = std::iter::once("impax")
            .chain(command.iter().map(|&a| if a == "FILE" { p } else { a }))
            .collect();
        let run = impax_cli::invoke(&args);
        if let Err(why) = impax_cli::contract::check(&run) {
            panic!("{args:?} on {:?}: {why}", String::from_utf8_lossy(data));
        }
    }
}
