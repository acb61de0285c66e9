//! `cargo xtask lengths`: hand-written Rust files over [`MAX_FILE_LINES`] lines and functions
//! over [`MAX_FUNCTION_LINES`] (from the `fn` line to the closing brace, doc comments and
//! attributes not counted), in every tracked file outside the generated ones
//! (`core/src/generated/`). The limits are the developers' guide's: a file a reader can hold in
//! their head.

use std::path::{Path, PathBuf};

use anyhow::{bail, Result};
use syn::spanned::Spanned;
use syn::visit::Visit;

use crate::rust_files::{is_generated, parse, tracked_rust_files};

/// Lines a hand-written file may have.
pub const MAX_FILE_LINES: usize = 600;
/// Lines a function may have.
pub const MAX_FUNCTION_LINES: usize = 150;

/// A file or function over its limit.
#[derive(Debug, PartialEq, Eq)]
pub struct Over {
    pub file: PathBuf,
    /// `None` for the file itself.
    pub function: Option<String>,
    pub line: usize,
    pub lines: usize,
}

/// Collects the functions (free, in impls, in traits; nested ones too) over the limit.
struct Functions<'a> {
    file: &'a Path,
    owner: Vec<String>,
    out: &'a mut Vec<Over>,
}

impl Functions<'_> {
    fn check(&mut self, name: &syn::Ident, sig: &syn::Signature, block: &syn::Block) {
        let start = sig.fn_token.span.start().line;
        let end = block.brace_token.span.close().end().line;
        let lines = end + 1 - start;
        if lines > MAX_FUNCTION_LINES {
            let mut path = self.owner.clone();
            path.push(name.to_string());
            self.out.push(Over {
                file: self.file.to_path_buf(),
                function: Some(path.join("::")),
                line: start,
                lines,
            });
        }
    }
}

/// The type an impl block is for, as written (`Bearing<Z, S>` → `Bearing`).
fn self_type_name(ty: &syn::Type) -> String {
    match ty {
        syn::Type::Path(p) => p
            .path
            .segments
            .last()
            .map_or_else(|| "?".into(), |s| s.ident.to_string()),
        other => format!("<{}>", other.span().start().line),
    }
}

impl<'ast> Visit<'ast> for Functions<'_> {
    fn visit_item_fn(&mut self, f: &'ast syn::ItemFn) {
        self.check(&f.sig.ident, &f.sig, &f.block);
        syn::visit::visit_item_fn(self, f);
    }

    fn visit_item_impl(&mut self, i: &'ast syn::ItemImpl) {
        self.owner.push(self_type_name(&i.self_ty));
        syn::visit::visit_item_impl(self, i);
        self.owner.pop();
    }

    fn visit_impl_item_fn(&mut self, f: &'ast syn::ImplItemFn) {
        self.check(&f.sig.ident, &f.sig, &f.block);
        syn::visit::visit_impl_item_fn(self, f);
    }

    fn visit_item_trait(&mut self, t: &'ast syn::ItemTrait) {
        self.owner.push(t.ident.to_string());
        syn::visit::visit_item_trait(self, t);
        self.owner.pop();
    }

    fn visit_trait_item_fn(&mut self, f: &'ast syn::TraitItemFn) {
        if let Some(block) = &f.default {
            self.check(&f.sig.ident, &f.sig, block);
        }
        syn::visit::visit_trait_item_fn(self, f);
    }

    fn visit_item_mod(&mut self, m: &'ast syn::ItemMod) {
        self.owner.push(m.ident.to_string());
        syn::visit::visit_item_mod(self, m);
        self.owner.pop();
    }
}

/// Everything over a limit in the repository's hand-written Rust files.
pub fn find(root: &Path) -> Result<Vec<Over>> {
    let mut over = Vec::new();
    for file in tracked_rust_files(root)? {
        if is_generated(&file) {
            continue;
        }
        let text = std::fs::read_to_string(root.join(&file))?;
        let lines = text.lines().count();
        if lines > MAX_FILE_LINES {
            over.push(Over {
                file: file.clone(),
                function: None,
                line: 1,
                lines,
            });
        }
        let parsed = parse(root, &file)?;
        Functions {
            file: &file,
            owner: Vec::new(),
            out: &mut over,
        }
        .visit_file(&parsed);
    }
    Ok(over)
}

pub fn run(root: &Path) -> Result<()> {
    let over = find(root)?;
    for o in &over {
        match &o.function {
            None => println!(
                "{}: {} lines (file; limit {MAX_FILE_LINES})",
                o.file.display(),
                o.lines
            ),
            Some(f) => println!(
                "{}:{}: fn {f}: {} lines (limit {MAX_FUNCTION_LINES})",
                o.file.display(),
                o.line,
                o.lines
            ),
        }
    }
    if !over.is_empty() {
        bail!(
            "{} file(s) or function(s) over their length limit",
            over.len()
        );
    }
    println!(
        "no hand-written file over {MAX_FILE_LINES} lines, no function over {MAX_FUNCTION_LINES}"
    );
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn counts_a_function_from_its_fn_line_to_its_closing_brace() {
        let body = "    let _x = 1;\n".repeat(MAX_FUNCTION_LINES - 2);
        let source = format!(
            "/// doc\nfn short() {{\n{body}}}\nimpl Foo {{\n    fn long() {{\n{body}    let _y = 2;\n    }}\n}}\n"
        );
        let parsed = syn::parse_file(&source).unwrap();
        let mut out = Vec::new();
        Functions {
            file: Path::new("x.rs"),
            owner: Vec::new(),
            out: &mut out,
        }
        .visit_file(&parsed);
        assert_eq!(out.len(), 1, "{out:?}");
        assert_eq!(out[0].function.as_deref(), Some("Foo::long"));
        assert_eq!(out[0].lines, MAX_FUNCTION_LINES + 1);
    }
}
