// Injected into a copy of report.html by tests/cli_report_html.sh: once the
// page and its images loaded, writes one line into the page (read back with
// chromium --dump-dom): every image decoded (naturalWidth > 0) and every
// in-page link (#id) pointing at an element that exists. Then what a reader
// sees in a window 1280 x 800: the per-paper table starts within the first
// 800 px; with every <details> opened, the page does not scroll sideways and
// no element's right edge is past the window, except inside a box that
// scrolls sideways itself (a wide table's .table-wrap), which must fit; no
// cell's content is cut (scrollWidth <= clientWidth); the verdicts
// "reproduced" and "not reproduced" are shown in different colours.
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
  // (Headless Chromium's window leaves a shorter viewport to --dump-dom than
  // to --screenshot: the first screen is the top 800 px of the page,
  // measured from the page's top.)
  var W = 1280, H = 800;
  if (window.innerWidth !== W) bad.push('window ' + window.innerWidth + ' px wide, not ' + W);
  var first = document.querySelector('.papers table');
  if (!first) bad.push('no per-paper table (.papers table)');
  else if (first.getBoundingClientRect().top + window.scrollY > H)
    bad.push('per-paper table at ' + Math.round(first.getBoundingClientRect().top + window.scrollY) +
             ' px, below the first screen');

  var folded = document.querySelectorAll('details');
  for (var d = 0; d < folded.length; d++) folded[d].open = true;
  var width = window.innerWidth;
  // An element inside a box that scrolls sideways may be wider than the
  // window: the box shows it by scrolling; the box itself is measured.
  function scrolls(el) {
    var o = getComputedStyle(el).overflowX;
    return o === 'auto' || o === 'scroll' || o === 'hidden';
  }
  var widest = null, right = width;
  var all = document.body.getElementsByTagName('*');
  for (var a = 0; a < all.length; a++) {
    var el = all[a], inside = false;
    for (var up = el.parentElement; up && up !== document.body; up = up.parentElement)
      if (scrolls(up)) { inside = true; break; }
    if (inside) continue;
    var r = el.getBoundingClientRect();
    if (r.width > 0 && r.right > right + 0.5) { right = r.right; widest = el; }
  }
  function label(el) {
    var s = el.tagName.toLowerCase() + (el.className ? '.' + String(el.className).split(' ').join('.') : '');
    var t = el.closest('table');
    if (t) {
      var n = Array.prototype.indexOf.call(document.querySelectorAll('table'), t) + 1;
      s += ' in table ' + n + ' (' + t.rows[0].cells.length + ' columns)';
    }
    return s;
  }
  if (widest)
    bad.push('widest element ' + label(widest) + ' wider than the window (ends at ' +
             Math.round(right) + ' of ' + width + ' px)');
  var page = document.documentElement.scrollWidth;
  if (page > width) bad.push('page scrolls sideways (' + page + ' of ' + width + ' px)');
  var cells = document.querySelectorAll('td, th');
  var clipped = 0, example = '';
  for (var c = 0; c < cells.length; c++) {
    if (cells[c].scrollWidth > cells[c].clientWidth) {
      if (!clipped) example = cells[c].textContent.slice(0, 40);
      clipped++;
    }
  }
  if (clipped) bad.push(clipped + ' cells cut, e.g. "' + example + '"');

  // A verdict cell's colour: the innermost element of the cell that holds
  // only the word.
  function colour(word) {
    for (var k = 0; k < cells.length; k++) {
      // a heading cell (the per-paper table's "reproduced" column) is no verdict
      if (cells[k].tagName !== 'TD' || cells[k].textContent.replace(/\s+/g, ' ').trim() !== word) continue;
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
