// The summary table: click a heading to sort by it (again to reverse); rows start worst first.
(function () {
  'use strict';
  var table = document.getElementById('summary');
  if (!table) return;
  var heads = table.tHead.rows[0].cells;
  var body = table.tBodies[0];
  function sortBy(col, dir) {
    var numeric = heads[col].getAttribute('data-type') === 'num';
    var rows = Array.prototype.slice.call(body.rows);
    rows.sort(function (a, b) {
      var x = a.cells[col].getAttribute('data-key'), y = b.cells[col].getAttribute('data-key');
      var c = numeric ? parseFloat(x) - parseFloat(y) : x.localeCompare(y);
      if (c === 0) c = a.getAttribute('data-rank') - b.getAttribute('data-rank');
      return dir * c;
    });
    rows.forEach(function (r) { body.appendChild(r); });
    for (var i = 0; i < heads.length; i++) heads[i].removeAttribute('aria-sort');
    heads[col].setAttribute('aria-sort', dir > 0 ? 'ascending' : 'descending');
  }
  Array.prototype.forEach.call(heads, function (th, col) {
    th.tabIndex = 0;
    var go = function () {
      var dir = th.getAttribute('aria-sort') === 'descending' ? 1 : -1;
      // Text sorts A..Z first; the result column FAIL (0) first.
      if (!th.getAttribute('aria-sort') && (th.getAttribute('data-type') === 'text' || col === 1)) dir = 1;
      sortBy(col, dir);
    };
    th.addEventListener('click', go);
    th.addEventListener('keydown', function (e) { if (e.key === 'Enter' || e.key === ' ') { e.preventDefault(); go(); } });
  });
  // For the browser test: #sort=5,5 clicks those column headings in turn, as a user would.
  var m = /sort=([0-9,]+)/.exec(location.hash);
  if (m) m[1].split(',').forEach(function (c) { if (heads[+c]) heads[+c].click(); });
  // For the browser test: whether the page fits the window without horizontal scrolling.
  var fits = function () {
    document.body.setAttribute('data-fits', String(document.documentElement.scrollWidth <= window.innerWidth));
  };
  fits();
  window.addEventListener('resize', fits);
})();
