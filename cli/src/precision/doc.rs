//! A tiny document model written out twice: as Markdown and as one self-contained HTML page.

use std::fmt::Write as _;

/// A table: a header row and rows of cells (already formatted).
#[derive(Debug, Default)]
pub struct Table {
    /// The header cells.
    pub headers: Vec<String>,
    /// The rows, each as many cells as there are headers.
    pub rows: Vec<Vec<String>>,
}

impl Table {
    /// An empty table with these column headers.
    pub fn new<S: Into<String>>(headers: impl IntoIterator<Item = S>) -> Table {
        Table {
            headers: headers.into_iter().map(Into::into).collect(),
            rows: Vec::new(),
        }
    }

    /// Appends a row.
    pub fn row(&mut self, cells: Vec<String>) {
        self.rows.push(cells);
    }
}

/// One block of the report.
#[derive(Debug)]
pub enum Block {
    /// A heading of level 1 to 3.
    Heading(u8, String),
    /// A paragraph; `code` in backticks and **bold** are rendered in both outputs.
    Text(String),
    /// A bullet list.
    List(Vec<String>),
    /// A table.
    Table(Table),
    /// A table folded away under a summary line (`<details>` in both outputs).
    Folded(String, Table),
    /// An SVG picture: its file name beside the report, its markup, a caption.
    Picture {
        /// The file name beside the report.
        file: String,
        /// The SVG markup.
        svg: String,
        /// What it shows.
        caption: String,
    },
}

/// The report: blocks in order.
#[derive(Debug, Default)]
pub struct Doc {
    /// The blocks, in reading order.
    pub blocks: Vec<Block>,
}

impl Doc {
    /// Appends a heading of `level` 1 to 3.
    pub fn heading(&mut self, level: u8, text: impl Into<String>) {
        self.blocks.push(Block::Heading(level, text.into()));
    }

    /// Appends a paragraph.
    pub fn text(&mut self, text: impl Into<String>) {
        self.blocks.push(Block::Text(text.into()));
    }

    /// Appends a bullet list.
    pub fn list(&mut self, items: Vec<String>) {
        self.blocks.push(Block::List(items));
    }

    /// Appends a table.
    pub fn table(&mut self, table: Table) {
        self.blocks.push(Block::Table(table));
    }

    /// Appends a table folded under `summary`.
    pub fn folded(&mut self, summary: impl Into<String>, table: Table) {
        self.blocks.push(Block::Folded(summary.into(), table));
    }

    /// Appends an SVG picture saved as `file`, with a caption.
    pub fn picture(&mut self, file: String, svg: String, caption: String) {
        self.blocks.push(Block::Picture { file, svg, caption });
    }

    /// The report as GitHub-flavoured Markdown; pictures are linked by file name.
    pub fn markdown(&self) -> String {
        let mut out = String::new();
        for block in &self.blocks {
            match block {
                Block::Heading(level, text) => {
                    let _ = writeln!(out, "{} {text}\n", "#".repeat(usize::from(*level)));
                }
                Block::Text(text) => {
                    let _ = writeln!(out, "{text}\n");
                }
                Block::List(items) => {
                    for item in items {
                        let _ = writeln!(out, "- {item}");
                    }
                    out.push('\n');
                }
                Block::Table(table) => markdown_table(&mut out, table),
                Block::Folded(summary, table) => {
                    let _ = writeln!(out, "<details><summary>{summary}</summary>\n");
                    markdown_table(&mut out, table);
                    out.push_str("</details>\n\n");
                }
                Block::Picture { file, caption, .. } => {
                    let _ = writeln!(out, "![{}]({file})\n\n*{caption}*\n", escape_md(caption));
                }
            }
        }
        out
    }

    /// The report as one HTML page with every picture inline.
    pub fn html(&self, title: &str) -> String {
        let mut out = String::new();
        let _ = write!(
            out,
            "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>{}</title>\n<style>\n{STYLE}\n</style>\n</head>\n<body>\n",
            escape_html(title)
        );
        for block in &self.blocks {
            match block {
                Block::Heading(level, text) => {
                    let _ = writeln!(out, "<h{level}>{}</h{level}>", inline_html(text));
                }
                Block::Text(text) => {
                    let _ = writeln!(out, "<p>{}</p>", inline_html(text));
                }
                Block::List(items) => {
                    out.push_str("<ul>\n");
                    for item in items {
                        let _ = writeln!(out, "<li>{}</li>", inline_html(item));
                    }
                    out.push_str("</ul>\n");
                }
                Block::Table(table) => html_table(&mut out, table),
                Block::Folded(summary, table) => {
                    let _ = writeln!(out, "<details><summary>{}</summary>", inline_html(summary));
                    html_table(&mut out, table);
                    out.push_str("</details>\n");
                }
                Block::Picture { svg, caption, .. } => {
                    let _ = writeln!(
                        out,
                        "<figure>\n{}\n<figcaption>{}</figcaption>\n</figure>",
                        strip_xml_declaration(svg),
                        inline_html(caption)
                    );
                }
            }
        }
        out.push_str("</body>\n</html>\n");
        out
    }
}

const STYLE: &str = "\
body{font-family:system-ui,sans-serif;max-width:1100px;margin:2em auto;padding:0 1em;color:#222}
table{border-collapse:collapse;margin:1em 0;font-size:.85em}
th,td{border:1px solid #ccc;padding:.2em .5em;text-align:right}
th{background:#f0f0f0}
td:first-child,th:first-child{text-align:left}
code{background:#f4f4f4;padding:0 .2em}
figure{margin:1.5em 0}
figure svg{max-width:100%;height:auto}
figcaption{font-size:.9em;color:#555}";

fn markdown_table(out: &mut String, table: &Table) {
    let cells = |row: &[String]| {
        let escaped: Vec<String> = row.iter().map(|c| c.replace('|', "\\|")).collect();
        format!("| {} |", escaped.join(" | "))
    };
    let _ = writeln!(out, "{}", cells(&table.headers));
    let rule: Vec<String> = table
        .headers
        .iter()
        .enumerate()
        .map(|(k, _)| if k == 0 { ":--" } else { "--:" }.to_owned())
        .collect();
    let _ = writeln!(out, "|{}|", rule.join("|"));
    for row in &table.rows {
        let _ = writeln!(out, "{}", cells(row));
    }
    out.push('\n');
}

fn html_table(out: &mut String, table: &Table) {
    out.push_str("<table>\n<thead><tr>");
    for h in &table.headers {
        let _ = write!(out, "<th>{}</th>", inline_html(h));
    }
    out.push_str("</tr></thead>\n<tbody>\n");
    for row in &table.rows {
        out.push_str("<tr>");
        for c in row {
            let _ = write!(out, "<td>{}</td>", inline_html(c));
        }
        out.push_str("</tr>\n");
    }
    out.push_str("</tbody>\n</table>\n");
}

/// `&`, `<`, `>` and `"` escaped.
pub fn escape_html(text: &str) -> String {
    text.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
        .replace('"', "&quot;")
}

/// Brackets escaped, for an image's alt text.
fn escape_md(text: &str) -> String {
    text.replace('[', "\\[").replace(']', "\\]")
}

/// Escapes `text` and renders `code` spans, **bold** and `[text](link)` links.
fn inline_html(text: &str) -> String {
    let escaped = escape_html(text);
    let mut out = String::new();
    let mut code = false;
    for (k, part) in escaped.split('`').enumerate() {
        if k > 0 {
            out.push_str(if code { "</code>" } else { "<code>" });
            code = !code;
        }
        if code {
            out.push_str(part);
        } else {
            out.push_str(&links(&bold(part)));
        }
    }
    out
}

fn bold(text: &str) -> String {
    let mut out = String::new();
    for (k, part) in text.split("**").enumerate() {
        if k > 0 {
            out.push_str(if k % 2 == 1 { "<b>" } else { "</b>" });
        }
        out.push_str(part);
    }
    out
}

/// `[text](target)` as an HTML link.
fn links(text: &str) -> String {
    let mut out = String::new();
    let mut rest = text;
    while let Some(open) = rest.find('[') {
        let Some(mid) = rest[open..].find("](").map(|m| open + m) else {
            break;
        };
        let Some(close) = rest[mid..].find(')').map(|c| mid + c) else {
            break;
        };
        out.push_str(&rest[..open]);
        let _ = write!(
            out,
            "<a href=\"{}\">{}</a>",
            &rest[mid + 2..close],
            &rest[open + 1..mid]
        );
        rest = &rest[close + 1..];
    }
    out.push_str(rest);
    out
}

/// An SVG document without its `<?xml …?>` line, for inlining into HTML.
fn strip_xml_declaration(svg: &str) -> &str {
    match svg.find("<svg") {
        Some(start) => &svg[start..],
        None => svg,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn both_outputs_hold_every_block() {
        let mut doc = Doc::default();
        doc.heading(1, "Report");
        doc.text("a `x < y` and **bold** [link](a.svg)");
        let mut t = Table::new(["family", "rate"]);
        t.row(vec!["star".to_owned(), "1|2".to_owned()]);
        doc.table(t);
        doc.picture("p.svg".into(), "<?xml?>\n<svg></svg>".into(), "cap".into());
        let md = doc.markdown();
        assert!(md.starts_with("# Report\n"));
        assert!(md.contains("| star | 1\\|2 |"));
        assert!(md.contains("![cap](p.svg)"));
        let html = doc.html("t");
        assert!(html.contains("<code>x &lt; y</code>"), "{html}");
        assert!(html.contains("<b>bold</b>"));
        assert!(html.contains("<a href=\"a.svg\">link</a>"));
        assert!(html.contains("<figure>\n<svg></svg>"));
        assert!(html.contains("<td>star</td>"));
    }
}
