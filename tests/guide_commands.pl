#!/usr/bin/perl
# The ./workbook command lines of guides, or those that scripts run, one a line from ./workbook on.
#   guide_commands.pl guide FILE.md...   each line of a code block (fenced, or indented by four
#                                        spaces) that runs ./workbook; not an inline mention in prose
#   guide_commands.pl run SCRIPT...      each ./workbook (or "$dir/workbook") at a command's place in
#                                        code: not inside a string, a grep pattern or a comment
# Usage: perl guide_commands.pl guide|run FILE...
use strict;
use warnings;

my $mode = shift @ARGV // '';
die "usage: guide_commands.pl guide|run FILE...\n" unless $mode eq 'guide' || $mode eq 'run';

sub read_text {
  my ($file) = @_;
  open(my $in, '<', $file) or die "$file: $!\n";
  local $/;
  my $text = <$in>;
  close $in;
  return $text;
}

sub guide_commands {
  my ($file) = @_;
  my $fence = 0;
  for my $line (split /\n/, read_text($file)) {
    if ($line =~ /^\s*```/) { $fence = !$fence; next; }
    next unless $fence || $line =~ /^ {4,}\.\/workbook\b/;
    next unless $line =~ /^\s*(?:\$\s+)?(\.\/workbook\b.*)$/;
    (my $command = $1) =~ s/\s+#.*//;
    print "$command\n";
  }
}

# A workbook word, and what may stand between a command's place and it (env, nice, assignments).
my $word = qr/(?:\.\/workbook|"\$\{?\w+\}?\/workbook")(?=[\s);]|$)/;
my $prefix = qr/(?:\s*(?:env(?:\s+-u\s+\w+)*|nice\s+-n\s+\d+|\w+=(?:"[^"]*"|\S*)))*\s*$/;
my $place = qr/(?:^|&&|\|\||[;({|!]|\bif|\bthen|\bdo|\belse)\s*$/;

sub run_commands {
  my ($file) = @_;
  my $text = read_text($file);
  $text =~ s/\\\n/ /g;    # continued lines are one
  my @stack = ('c');      # c code, p code in ( ) or $( ), d a "string", s a 'string'
  my $start = 0;          # where the current line began
  for (my $i = 0; $i < length $text; ++$i) {
    my $c = substr($text, $i, 1);
    my $top = $stack[-1];
    if ($c eq "\n") { $start = $i + 1; next; }
    if ($top eq 's') { pop @stack if $c eq "'"; next; }
    if ($top eq 'd') {
      if ($c eq '\\') { ++$i; }
      elsif ($c eq '"') { pop @stack; }
      elsif (substr($text, $i, 2) eq '$(') { push @stack, 'p'; ++$i; }
      next;
    }
    if ($c eq '#' && ($i == $start || substr($text, $i - 1, 1) =~ /\s/)) {    # a comment
      my $end = index($text, "\n", $i);
      $i = ($end < 0 ? length $text : $end) - 1;
      next;
    }
    if (substr($text, $i) =~ /^$word/) {
      (my $before = substr($text, $start, $i - $start)) =~ s/$prefix//;
      if ($before =~ $place) {
        my $end = index($text, "\n", $i);
        (my $line = substr($text, $i, ($end < 0 ? length $text : $end) - $i)) =~ s/^"[^"]*"/.\/workbook/;
        print "$line\n";
      }
    }
    if ($c eq '\\') { ++$i; }
    elsif ($c eq "'") { push @stack, 's'; }
    elsif ($c eq '"') { push @stack, 'd'; }
    elsif ($c eq '(') { push @stack, 'p'; }
    elsif ($c eq ')') { pop @stack if $top eq 'p'; }
  }
}

for my $file (@ARGV) {
  if ($mode eq 'guide') { guide_commands($file); } else { run_commands($file); }
}
