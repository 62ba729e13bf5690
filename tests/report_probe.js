// Injected into a copy of report.html by tests/cli_report_html.sh: once the
// page and its images loaded, writes one line into the page (read back with
// chromium --dump-dom): every image decoded (naturalWidth > 0) and every
// in-page link (#id) pointing at an element that exists. Then what a reader
// sees in a window 1400 px wide: the per-experiment summary starts within
// the first 900 px; with every <details> opened, no table is wider than the
// window and no cell's content is cut (scrollWidth <= clientWidth); the
// verdicts "reproduced" and "not reproduced" are shown in different colours.
window.addEventListener('load', function () {
  var bad = [];
  for (var i = 0; i < document.images.length; i++) {
    var img = document.images[i];
    if (!img.complete || img.naturalWidth === 0) bad.push('image ' + img.getAttribute('src'));
  }
  var links = document.querySelectorAll('a[href^="#"]');
  for (var j = 0; j < links.length; j++) {
    var id = decodeURIComponent(links[j].getAttribute('href').slice(1));
    if (!document.getElementById(id)) bad.push('link #' + id);
  }

  // The width the test asked for, or the checks below measure another page.
  // (Headless Chromium's window of 900 px leaves a shorter viewport to
  // --dump-dom than to --screenshot: the first screen is the top 900 px of
  // the page, measured from the page's top.)
  if (window.innerWidth !== 1400) bad.push('window ' + window.innerWidth + ' px wide, not 1400');
  var first = document.querySelector('.summary li');
  if (!first) bad.push('no summary (.summary li)');
  else if (first.getBoundingClientRect().bottom + window.scrollY > 900)
    bad.push('summary at ' + Math.round(first.getBoundingClientRect().top + window.scrollY) +
             ' px, below the first screen');

  var folded = document.querySelectorAll('details');
  for (var d = 0; d < folded.length; d++) folded[d].open = true;
  var width = document.documentElement.clientWidth;
  var tables = document.querySelectorAll('table');
  for (var t = 0; t < tables.length; t++) {
    // a table that scrolls inside itself (pandoc's default) hides its excess
    var box = tables[t].getBoundingClientRect();
    var hidden = tables[t].scrollWidth - tables[t].clientWidth;
    var name = 'table ' + (t + 1);
    if (box.right + hidden > width + 0.5)
      bad.push(name + ' wider than the window (ends at ' + Math.round(box.right + hidden) + ' of ' +
               width + ' px)');
    else if (hidden > 0) bad.push(name + ' cut (' + hidden + ' px behind a scrollbar)');
  }
  var cells = document.querySelectorAll('td, th');
  var clipped = 0, example = '';
  for (var c = 0; c < cells.length; c++) {
    if (cells[c].scrollWidth > cells[c].clientWidth) {
      if (!clipped) example = cells[c].textContent.slice(0, 40);
      clipped++;
    }
  }
  if (clipped) bad.push(clipped + ' cells cut, e.g. "' + example + '"');
  var page = document.documentElement.scrollWidth;
  if (page > width) bad.push('page scrolls sideways (' + page + ' of ' + width + ' px)');

  // A verdict cell's colour: the innermost element of the cell that holds
  // only the word.
  function colour(word) {
    for (var k = 0; k < cells.length; k++) {
      if (cells[k].textContent.replace(/\s+/g, ' ').trim() !== word) continue;
      var el = cells[k];
      while (el.firstElementChild) el = el.firstElementChild;
      var s = getComputedStyle(el);
      return s.color + ' on ' + s.backgroundColor + (el === cells[k] ? '' : ' / ' +
             getComputedStyle(el.parentElement).backgroundColor);
    }
    return null;
  }
  var yes = colour('reproduced'), no = colour('not reproduced');
  if (!yes || !no) bad.push('no verdict cell "' + (yes ? 'not reproduced' : 'reproduced') + '"');
  else if (yes === no) bad.push('verdicts in one colour (' + yes + ')');

  var pre = document.createElement('pre');
  pre.textContent = 'NL-' + 'PROBE images=' + document.images.length + ' links=' + links.length +
                    (bad.length ? ' BROKEN: ' + bad.join(', ') : ' OK');
  document.body.appendChild(pre);
});
