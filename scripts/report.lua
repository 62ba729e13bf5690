-- report.lua: the pandoc filter behind report.html (scripts/noiselab,
-- write_html). REPORT.md marks a verdict in bold (italic for a row by
-- construction), which reads on the forge as it is; in the page each verdict,
-- alone or counted ("3 partly"), becomes a span with a class per outcome,
-- coloured by scripts/report.css. A column named like max_abs_over_bound
-- may break after its underscores, so that a table of many such columns
-- fits the window without cutting a word elsewhere.

local class_of = {
  ["reproduced"] = "v-reproduced",
  ["partly"] = "v-partly",
  ["not reproduced"] = "v-not",
  -- fitted and selected rows are not verdicts: colours of their own, never
  -- the counted ones, so a failed fit does not read as a failed verdict
  ["consistent after fit"] = "v-consistent",
  ["consistent after selection"] = "v-consistent",
  ["partly consistent after fit"] = "v-fit-partly",
  ["partly consistent after selection"] = "v-fit-partly",
  ["not consistent after fit"] = "v-fit-not",
  ["not consistent after selection"] = "v-fit-not",
  ["by construction"] = "v-construction",
  ["see figure"] = "v-figure",
}

local function mark(el)
  local text = pandoc.utils.stringify(el)
  local word = text:gsub("^%d+ ", "")
  local class = class_of[word]
  if class then
    return pandoc.Span({el}, pandoc.Attr("", {"verdict", class}))
  end
end

local function breakable(el)
  if #el.text > 6 and el.text:find("_", 2, true) then
    local out = {}
    for part in el.text:gmatch("[^_]*_?") do
      if part ~= "" then
        out[#out + 1] = pandoc.Str(part)
        if part:sub(-1) == "_" then out[#out + 1] = pandoc.RawInline("html", "<wbr>") end
      end
    end
    return out
  end
end

-- Every table in a box of the window's width that scrolls sideways
-- (scripts/report.css, .table-wrap): a table of 24 columns whose numbers
-- never break is wider than a 1280 px window, and the page must not be.
-- Tables of many columns (an experiment's full table: 20 and more) also in
-- a smaller type, so that most fit without scrolling.
local function narrow(el)
  local n = #el.colspecs
  local classes = {"table-wrap"}
  if n > 12 then classes[2] = n > 18 and "widest" or "wide" end
  return pandoc.Div({el}, pandoc.Attr("", classes))
end

return {{Strong = mark, Emph = mark, Str = breakable}, {Table = narrow}}
