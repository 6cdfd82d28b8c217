//! Where a mechanism file's error is: the line of the field an error names
//! (`joint[theta2].parent`, `body[rod 1].com[1]`, `q[0]`), so that a front end showing the
//! file can say `line 27: joint[theta2].parent: …`.
//!
//! The TOML reader already gives the line and column of a syntax error; the checks after it
//! name fields as the file spells them ([`MechanismFile`](super::MechanismFile)'s module docs),
//! which this module finds back in the text: a `[[body]]`, `[[joint]]` or `[[contact]]` table
//! by its `name` (a joint without one by its `child`, a contact by its `body`, or as
//! `BODY[k]` by its position among the contacts), then the key's line in that table (the
//! table's header line if the key is absent). Top-level keys are searched before the first
//! table.
//!
//! ```
//! use impax::scenario::{file_error_message, MechanismFile};
//! let text = "q = [0.1]\n[[body]]\nname = \"rod\"\nmass = -1.0\ninertia = 0.1\n\n\
//!             [[joint]]\ntype = \"revolute\"\nparent = \"world\"\nchild = \"rod\"\n";
//! let err = MechanismFile::parse(text)?.planar().unwrap_err();
//! assert_eq!(err.field(), "body[rod].mass");
//! assert!(file_error_message(text, &err).starts_with("line 4: body[rod].mass: "));
//! let bad = "[[body]]\nname = \"rod\"\nmas = 1.0\n";
//! let err = MechanismFile::parse(bad).unwrap_err();
//! assert!(file_error_message(bad, &err).starts_with("line 3, column 1: unknown field `mas`"));
//! # Ok::<(), impax::Error>(())
//! ```

use crate::error::Error;

/// One `[[kind]]` table of the file: its header's line and its keys' lines.
struct Table<'a> {
    kind: &'a str,
    header: usize,
    keys: Vec<(&'a str, &'a str, usize)>,
}

impl<'a> Table<'a> {
    fn key(&self, key: &str) -> Option<usize> {
        self.keys.iter().find(|(k, _, _)| *k == key).map(|k| k.2)
    }

    /// A key's string value (`name = "rod 1"` → `rod 1`).
    fn text(&self, key: &str) -> Option<&'a str> {
        let (_, v, _) = self.keys.iter().find(|(k, _, _)| *k == key)?;
        let v = v.trim();
        let quote = v.chars().next().filter(|c| *c == '"' || *c == '\'')?;
        let rest = &v[1..];
        rest.find(quote).map(|end| &rest[..end])
    }
}

/// `key = value` of a line (comments and blank lines give `None`).
fn key_value(line: &str) -> Option<(&str, &str)> {
    let line = line.trim();
    if line.starts_with('#') || line.starts_with('[') {
        return None;
    }
    let (k, v) = line.split_once('=')?;
    let k = k.trim().trim_matches(|c| c == '"' || c == '\'');
    Some((k, v))
}

/// The top-level keys and the tables of a mechanism file's text (lines counted from 1).
fn tables(text: &str) -> (Vec<(&str, usize)>, Vec<Table<'_>>) {
    let mut top = Vec::new();
    let mut tables: Vec<Table<'_>> = Vec::new();
    for (i, line) in text.lines().enumerate() {
        let n = i + 1;
        let t = line.trim();
        if let Some(head) = t.strip_prefix("[[") {
            if let Some(end) = head.find("]]") {
                tables.push(Table {
                    kind: head[..end].trim(),
                    header: n,
                    keys: Vec::new(),
                });
                continue;
            }
        }
        if let Some((k, v)) = key_value(line) {
            match tables.last_mut() {
                Some(table) => table.keys.push((k, v, n)),
                None => top.push((k, n)),
            }
        }
    }
    (top, tables)
}

/// The line (from 1) of the field an error of a mechanism file names, if the text has it.
///
/// `field` is as the errors spell it: `q`, `q[1]`, `gravity`, `body[NAME].KEY`,
/// `joint[NAME].KEY[i]`, `contact[NAME].KEY`, `body[NAME]`.
pub fn field_line(text: &str, field: &str) -> Option<usize> {
    let (top, tables) = tables(text);
    // `kind[NAME]` and the rest, or a top-level key.
    let Some((kind, rest)) = field
        .split_once('[')
        .filter(|(k, _)| matches!(*k, "body" | "joint" | "contact"))
    else {
        let key = field.split('[').next().unwrap_or(field);
        return top.iter().find(|(k, _)| *k == key).map(|k| k.1);
    };
    // The name may itself hold brackets (`foot[1]`): the table's part ends at the last `]`
    // before the key's `.`.
    let (name, key) = match rest.rfind("].") {
        Some(i) => (&rest[..i], Some(&rest[i + 2..])),
        None => (rest.strip_suffix(']').unwrap_or(rest), None),
    };
    let of_kind: Vec<&Table<'_>> = tables.iter().filter(|t| t.kind == kind).collect();
    let by_name = |t: &&&Table<'_>| match t.text("name") {
        Some(n) => n == name,
        None => match kind {
            "joint" => t.text("child") == Some(name),
            "contact" => t.text("body") == Some(name),
            _ => false,
        },
    };
    let table = of_kind.iter().find(by_name).or_else(|| {
        // A contact without a name, one of several on its body: `BODY[k]`, k its position.
        let (body, k) = name.strip_suffix(']')?.rsplit_once('[')?;
        let k: usize = k.parse().ok()?;
        of_kind
            .get(k)
            .filter(|t| t.text("name").is_none() && t.text("body") == Some(body))
    })?;
    let key = key.map(|k| k.split('[').next().unwrap_or(k));
    Some(key.and_then(|k| table.key(k)).unwrap_or(table.header))
}

/// An error of a mechanism file as one line that says where: `line L, column C: …` for a
/// syntax error, `line L: FIELD: …` when the field is found in the text, else the error's own
/// message.
pub fn file_error_message(text: &str, error: &Error) -> String {
    let message = error.to_string().replace('\n', " ");
    match error {
        Error::Syntax {
            at: Some((line, column)),
            message,
        } => format!("line {line}, column {column}: {message}"),
        Error::Syntax { .. } => message,
        other => match field_line(text, other.field()) {
            Some(line) => format!("line {line}: {message}"),
            None => message,
        },
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const FILE: &str = "\
name = \"two\"
q = [0.1, 0.2]

[[body]]
name = \"a\"
mass = 1.0

[[body]]
name = \"b\"
com = [0.0, 1.0]

[[joint]]
type = \"revolute\"
parent = \"world\"
child = \"a\"

[[joint]]
name = \"elbow\"
parent = \"a\"   # the first body
child = \"b\"

[[contact]]
body = \"b\"
point = [0.0, 1.0]

[[contact]]
body = \"b\"
";

    #[test]
    fn finds_tables_by_name_child_body_and_position() {
        assert_eq!(field_line(FILE, "q[1]"), Some(2));
        assert_eq!(field_line(FILE, "name"), Some(1));
        assert_eq!(field_line(FILE, "body[a].mass"), Some(6));
        assert_eq!(field_line(FILE, "body[b].com[1]"), Some(10));
        assert_eq!(field_line(FILE, "body[b].inertia"), Some(8)); // absent: the header
        assert_eq!(field_line(FILE, "body[b]"), Some(8));
        assert_eq!(field_line(FILE, "joint[a].parent"), Some(14)); // by its child
        assert_eq!(field_line(FILE, "joint[elbow].parent"), Some(19));
        assert_eq!(field_line(FILE, "contact[b[1]].point"), Some(26));
        assert_eq!(field_line(FILE, "contact[b[0]].point"), Some(24));
        assert_eq!(field_line(FILE, "joint[nope].parent"), None);
        assert_eq!(field_line(FILE, "gravity"), None);
        assert_eq!(field_line(FILE, "law"), None);
    }

    #[test]
    fn messages_say_where() {
        let e = Error::Invalid {
            field: "joint[elbow].parent".into(),
            reason: "`c` is not a body of the file".into(),
        };
        assert_eq!(
            file_error_message(FILE, &e),
            "line 19: joint[elbow].parent: `c` is not a body of the file"
        );
        let e = Error::Invalid {
            field: "speed".into(),
            reason: "nowhere".into(),
        };
        assert_eq!(file_error_message(FILE, &e), "speed: nowhere");
    }
}
