// SPDX-License-Identifier: BSD-3-Clause
#include "MainWindow.h"

#include "WheelGuard.h"

#include "ColorLegend.h"

#include "BrdfPlot.h"
#include "ComparisonWidget.h"
#include "MaterialEditor.h"
#include "ParameterPlot.h"
#include "ProfilePlot.h"
#include "ScanlineInspector.h"
#include "ShadingPanel.h"

#include "MeshIO.h"
#include "VtkCamera.h"
#include "shadinglab/model/Materials.h"

#include <cstring>
#include <vtkCellData.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>

#include <QAction>
#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QDragEnterEvent>
#include <QFileDialog>
#include <QFormLayout>
#include <QGroupBox>
#include <QLabel>
#include <QListWidget>
#include <QMenuBar>
#include <QMessageBox>
#include <QMimeData>
#include <QScrollArea>
#include <QScrollBar>
#include <QSlider>
#include <QSpinBox>
#include <QSplitter>
#include <QStackedWidget>
#include <QStatusBar>
#include <QTextBrowser>
#include <QTimer>
#include <QVBoxLayout>

#include <algorithm>
#include <fstream>
#include <sstream>

namespace shadinglab::gui
{

namespace
{
/// The docks' widths in pixels (the controls' at least, or as wide as they
/// need): at 1280 x 720 the two leave the panels more than half the width.
constexpr int kLectureDockWidth = 220;
constexpr int kControlsDockWidth = 250;
/// The characters a closed choice box shows ("Perspective-c..."): enough
/// to tell its choices apart.
constexpr int kChoiceCharacters = 10;
} // namespace

namespace
{

/// Plots re-read the panels this long after the last render, so a slider
/// drag re-renders at once and reads the framebuffers once it pauses.
constexpr int kPlotDelayMs = 60;

} // namespace

MainWindow::MainWindow(const SceneOptions& options)
  : Options(options)
  , View(new widgets::ComparisonWidget)
  , Plots(new QStackedWidget)
  , ProfileChart(new widgets::ProfilePlot)
  , BrdfChart(new widgets::BrdfPlot)
  , ParameterChart(new widgets::ParameterPlot)
  , Inspector(new widgets::ScanlineInspector)
  , Editor(new widgets::MaterialEditor)
  , SceneNames(new QListWidget)
  , Explanation(new QTextBrowser)
  , PlotTimer(new QTimer(this))
{
  this->setWindowTitle("ShadingLab explorer");
  this->setAcceptDrops(true);
  if (options.input)
  {
    this->Input = options.input;
  }
  this->Options.input = nullptr;

  auto* empty = new QLabel("(this scene has no plot)");
  empty->setAlignment(Qt::AlignCenter);
  this->Plots->addWidget(empty);
  this->Plots->addWidget(this->ProfileChart);
  this->Plots->addWidget(this->BrdfChart);
  this->Plots->addWidget(this->ParameterChart);
  this->Plots->addWidget(this->Inspector);
  auto* split = new QSplitter(Qt::Vertical);
  split->addWidget(this->View);
  split->addWidget(this->Plots);
  split->setStretchFactor(0, 3);
  split->setStretchFactor(1, 2);
  split->setSizes({ 600, 380 });
  this->setCentralWidget(split);

  // Left: the scenes and what each shows.
  auto* left = new QWidget;
  auto* leftLayout = new QVBoxLayout(left);
  for (const SceneInfo& info : SceneList())
  {
    auto* item = new QListWidgetItem(info.name, this->SceneNames);
    item->setToolTip(info.summary);
  }
  this->SceneNames->setMaximumHeight(230);
  left->setMaximumWidth(kLectureDockWidth);
  leftLayout->addWidget(new QLabel("<b>Scenes</b>"));
  leftLayout->addWidget(this->SceneNames);
  leftLayout->addWidget(this->Explanation, 1);
  auto* leftDock = new QDockWidget("Lecture", this);
  leftDock->setWidget(left);
  leftDock->setObjectName("LectureDock");
  leftDock->setFeatures(QDockWidget::DockWidgetClosable);
  this->addDockWidget(Qt::LeftDockWidgetArea, leftDock);
  connect(this->SceneNames, &QListWidget::currentTextChanged, this, [this](const QString& name) {
    if (this->Updating || name.toStdString() == this->Current.name)
    {
      return;
    }
    std::string error;
    if (!this->LoadScene(name.toStdString(), error))
    {
      QMessageBox::warning(this, "ShadingLab", QString::fromStdString(error));
    }
  });

  auto* rightDock = new QDockWidget("Controls", this);
  auto* scroll = new QScrollArea;
  QWidget* controlsRoot = this->BuildControls();
  // Choices shrink to a few characters (their full text in the popup), so
  // the dock's width is the panels', not the longest choice's.
  for (QComboBox* box : controlsRoot->findChildren<QComboBox*>())
  {
    box->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    box->setMinimumContentsLength(kChoiceCharacters);
  }
  // A long label goes above its field rather than widening the dock.
  for (QFormLayout* form : controlsRoot->findChildren<QFormLayout*>())
  {
    form->setRowWrapPolicy(QFormLayout::WrapLongRows);
  }
  scroll->setWidget(controlsRoot);
  scroll->setWidgetResizable(true);
  // As narrow as the controls can be (never clipped: no horizontal bar).
  const int controlsWidth = std::max(kControlsDockWidth,
    controlsRoot->minimumSizeHint().width() + scroll->verticalScrollBar()->sizeHint().width() +
      2 * scroll->frameWidth());
  scroll->setMinimumWidth(controlsWidth);
  scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
  rightDock->setWidget(scroll);
  rightDock->setObjectName("ControlsDock");
  rightDock->setFeatures(QDockWidget::DockWidgetClosable);
  // The wheel scrolls the dock; it changes a control only with its focus.
  new widgets::WheelGuard(scroll);
  this->addDockWidget(Qt::RightDockWidgetArea, rightDock);
  this->BuildMenus();
  // Both docks fold away (View menu, F7 and F8): the panels take the width.
  QMenu* panes = this->menuBar()->addMenu("&Panes");
  QAction* lecture = leftDock->toggleViewAction();
  lecture->setShortcut(QKeySequence(Qt::Key_F7));
  QAction* controls = rightDock->toggleViewAction();
  controls->setShortcut(QKeySequence(Qt::Key_F8));
  panes->addAction(lecture);
  panes->addAction(controls);
  // Once shown (the main window lays docks out from their size hints).
  QTimer::singleShot(0, this, [this, leftDock, rightDock, controlsWidth] {
    this->resizeDocks({ leftDock, rightDock }, { kLectureDockWidth, controlsWidth }, Qt::Horizontal);
  });

  this->PlotTimer->setSingleShot(true);
  this->PlotTimer->setInterval(kPlotDelayMs);
  connect(this->PlotTimer, &QTimer::timeout, this, &MainWindow::UpdatePlot);
  connect(this->View, &widgets::ComparisonWidget::rendered, this->PlotTimer,
    QOverload<>::of(&QTimer::start));
  connect(this->View, &widgets::ComparisonWidget::profileLineChanged, this->PlotTimer,
    QOverload<>::of(&QTimer::start));
  connect(this->View, &widgets::ComparisonWidget::currentPanelChanged, this,
    &MainWindow::OnPanelSelected);
}

MainWindow::~MainWindow() = default;

void MainWindow::BuildMenus()
{
  QMenu* file = this->menuBar()->addMenu("&File");
  file->addAction("&Open mesh...", this, [this] {
    const QString path =
      QFileDialog::getOpenFileName(this, "Open a mesh", QString(), MainWindow::MeshFileFilter());
    std::string error;
    if (!path.isEmpty() && !this->OpenMesh(path.toStdString(), error))
    {
      QMessageBox::warning(this, "ShadingLab", QString::fromStdString(error));
    }
  }, QKeySequence::Open);
  file->addAction("Save &screenshot...", this, [this] {
    const QString path =
      QFileDialog::getSaveFileName(this, "Save screenshot", "shadinglab.png", "PNG (*.png)");
    if (!path.isEmpty())
    {
      this->grab().save(path);
    }
  });
  file->addAction("Export plot &CSV...", this, [this] {
    const QString path =
      QFileDialog::getSaveFileName(this, "Export the plot's numbers", "profile.csv", "CSV (*.csv)");
    if (!path.isEmpty())
    {
      std::ofstream(path.toStdString()) << this->PlotCsv();
    }
  });
  file->addSeparator();
  file->addAction("&Quit", qApp, &QApplication::quit, QKeySequence::Quit);
  QMenu* view = this->menuBar()->addMenu("&View");
  view->addAction("&Reset camera", this, [this] {
    if (this->Current.explicitCamera)
    {
      this->View->SetCamera(this->Current.camera);
    }
    else
    {
      this->View->ResetCamera(this->Current.azimuth, this->Current.elevation,
        this->Current.zoom, this->Current.parallel);
    }
    this->View->RenderAll();
  });
}

QString MainWindow::MeshFileFilter()
{
  QStringList patterns;
  for (const std::string& ext : ReadableExtensions())
  {
    patterns << QString("*.%1").arg(QString::fromStdString(ext));
  }
  return QString("Meshes (%1);;All files (*)").arg(patterns.join(' '));
}

bool MainWindow::LoadScene(const std::string& name, std::string& error)
{
  SceneOptions options = this->Options;
  options.input = this->Input;
  Scene scene;
  try
  {
    scene = MakeScene(name, options);
  }
  catch (const std::exception& e)
  {
    error = e.what();
    return false;
  }
  this->Current = scene;
  this->Updating = true;
  this->View->SetPanels(scene.panels);
  this->View->setVisible(!scene.panels.empty());
  this->View->SetProfileLine(scene.line);
  this->View->View().lightAzimuth = scene.lightAzimuth;
  this->View->View().lightElevation = scene.lightElevation;
  this->View->View().lightIntensity = scene.lightIntensity;
  this->View->View().lightDistance = scene.lightDistance;
  this->View->View().lightKit = scene.lightKit;
  this->View->View().display = scene.display;
  this->ListArrays();
  this->LightAzimuth->setValue(static_cast<int>(scene.lightAzimuth));
  this->LightElevation->setValue(static_cast<int>(scene.lightElevation));
  this->LightIntensity->setValue(scene.lightIntensity);
  this->Perceived->setChecked(scene.perceived);
  this->ProfileChart->SetShowPerceived(scene.perceived);
  for (int i = 0; i < this->SceneNames->count(); ++i)
  {
    if (this->SceneNames->item(i)->text().toStdString() == name)
    {
      this->SceneNames->setCurrentRow(i);
    }
  }
  this->Updating = false;
  QString html = QString("<h3>%1</h3><p>%2</p><p><b>Formula.</b> %3</p>")
                   .arg(QString::fromStdString(scene.title))
                   .arg(QString::fromStdString(scene.explanation).toHtmlEscaped())
                   .arg(QString::fromStdString(scene.formula));
  if (this->Input && !scene.usesInput)
  {
    html += "<p><i>This scene builds its own mesh; your mesh shows in modes, silhouette, "
            "moon and metal.</i></p>";
  }
  this->Explanation->setHtml(html);
  this->CurrentStudy = scene.plot == PlotKind::Parameter ? RunStudy(scene, options) : Study();
  this->Plots->setCurrentIndex(static_cast<int>(scene.plot));
  if (auto* split = qobject_cast<QSplitter*>(this->Plots->parentWidget()))
  {
    // The inspector has no panels above it: it takes the whole height.
    split->setSizes(scene.plot == PlotKind::Scanline ? QList<int>{ 0, 1000 }
                                                     : QList<int>{ 600, 380 });
  }
  if (scene.explicitCamera)
  {
    this->View->SetCamera(scene.camera);
  }
  else
  {
    this->View->ResetCamera(scene.azimuth, scene.elevation, scene.zoom, scene.parallel);
  }
  this->OnPanelSelected(0);
  this->View->RenderAll();
  if (scene.plot == PlotKind::Brdf)
  {
    this->UpdateBrdfPlot();
  }
  this->statusBar()->showMessage(QString("scene %1: %2 panel(s)")
                                   .arg(QString::fromStdString(name))
                                   .arg(scene.panels.size()));
  return true;
}

void MainWindow::ReloadScene()
{
  if (this->Current.name.empty())
  {
    return;
  }
  std::string error;
  const std::string name = this->Current.name;
  // What the user set that the scene's own defaults would overwrite.
  const widgets::ViewState before = this->View->View();
  const render::Camera camera = render::CameraFromVtk(before.camera);
  this->Current.name.clear();
  if (!this->LoadScene(name, error))
  {
    this->statusBar()->showMessage(QString::fromStdString(error));
    QMessageBox::warning(this, "ShadingLab", QString::fromStdString(error));
    return;
  }
  widgets::ViewState& view = this->View->View();
  view.lightAzimuth = before.lightAzimuth;
  view.lightElevation = before.lightElevation;
  view.lightIntensity = before.lightIntensity;
  this->Updating = true;
  this->LightAzimuth->setValue(static_cast<int>(before.lightAzimuth));
  this->LightElevation->setValue(static_cast<int>(before.lightElevation));
  this->LightIntensity->setValue(before.lightIntensity);
  this->Updating = false;
  this->View->SetCamera(camera);
  this->View->RenderAll();
}

bool MainWindow::OpenMesh(const std::string& path, std::string& error)
{
  vtkSmartPointer<vtkPolyData> mesh;
  try
  {
    mesh.TakeReference(ReadMesh(path, this->Options.reading));
  }
  catch (const std::exception& e)
  {
    error = path + ": " + e.what();
    return false;
  }
  vtkSmartPointer<vtkPolyData> previous = this->Input;
  this->Input = mesh;
  const std::string target = this->Current.usesInput ? this->Current.name : "modes";
  this->Current.name.clear();
  if (!this->LoadScene(target, error))
  {
    this->Input = previous;
    error = path + ": " + error;
    return false;
  }
  this->setWindowTitle(QString("ShadingLab explorer - %1").arg(QString::fromStdString(path)));
  return true;
}

void MainWindow::OnRotation(int degrees)
{
  this->Options.rotation = degrees;
  if (this->Updating || this->Current.name != "orientation")
  {
    return;
  }
  const Scene rotated = MakeScene("orientation", this->Options);
  for (int i = 0; i < this->View->PanelCount() && i < static_cast<int>(rotated.panels.size()); ++i)
  {
    // The user's settings of the panel stay; the quad and its title change.
    widgets::PanelSpec spec = this->View->Panel(i)->Spec();
    spec.mesh = rotated.panels[i].mesh;
    spec.title = rotated.panels[i].title;
    this->View->SetPanelSpec(i, spec);
    this->Current.panels[i] = spec;
  }
  this->CurrentStudy.marker = degrees;
  this->UpdatePlot();
}

void MainWindow::OnPanelSelected(int index)
{
  const bool any = index >= 0 && index < this->View->PanelCount();
  // A scene without panels (scanline, brdf) has no panel to set: its
  // controls show nothing of the previous scene's.
  for (QWidget* control : std::initializer_list<QWidget*>{ this->Mode, this->Backend,
         this->Interpolation, this->Scan, this->ScanPrecision, this->Editor })
  {
    control->setEnabled(any);
  }
  if (!any)
  {
    this->PanelLabel->setText("(this scene has no shaded panel)");
    this->MaxError->setEnabled(false);
    this->Editor->SetMaterial(Material<double>());
    return;
  }
  const widgets::ShadingPanel* panel = this->View->Panel(index);
  const widgets::PanelSpec& spec = panel->Spec();
  this->Updating = true;
  this->PanelLabel->setText(QString("Panel %1: %2").arg(index + 1).arg(panel->Title()));
  this->Mode->setCurrentIndex(
    this->Mode->findData(static_cast<int>(spec.mode)));
  this->MaxError->setValue(spec.maxError);
  this->MaxError->setEnabled(spec.mode == render::ShadingMode::Auto);
  this->Backend->setCurrentIndex(this->Backend->findData(static_cast<int>(spec.backend)));
  this->Interpolation->setCurrentIndex(
    this->Interpolation->findData(static_cast<int>(spec.interpolation)));
  this->Scan->setCurrentIndex(this->Scan->findData(static_cast<int>(spec.scan)));
  this->ScanPrecision->setCurrentIndex(
    this->ScanPrecision->findData(static_cast<int>(spec.scanPrecision)));
  this->Editor->SetMaterial(spec.material);
  this->Updating = false;
}

void MainWindow::OnPanelEdited()
{
  if (this->Updating || this->View->PanelCount() == 0)
  {
    return;
  }
  const int index = this->View->CurrentPanel();
  widgets::PanelSpec spec = this->View->Panel(index)->Spec();
  spec.mode = static_cast<render::ShadingMode>(this->Mode->currentData().toInt());
  spec.maxError = this->MaxError->value();
  this->MaxError->setEnabled(spec.mode == render::ShadingMode::Auto);
  spec.interpolation =
    static_cast<render::InterpolationSpace>(this->Interpolation->currentData().toInt());
  spec.scan = static_cast<render::ScanConversion>(this->Scan->currentData().toInt());
  spec.scanPrecision =
    static_cast<render::ScanPrecision>(this->ScanPrecision->currentData().toInt());
  spec.material = this->Editor->GetMaterial();
  auto backend = static_cast<render::Backend>(this->Backend->currentData().toInt());
  if (spec.scan == render::ScanConversion::Incremental && backend != render::Backend::CPU)
  {
    // The lecture's DDA is the CPU renderer's: the panel moves there.
    backend = render::Backend::CPU;
    this->Backend->setCurrentIndex(this->Backend->findData(static_cast<int>(backend)));
    this->statusBar()->showMessage("the incremental scan is the CPU renderer's: panel moved to CPU");
  }
  if (!render::SupportsModel(spec.mode, spec.material.model))
  {
    this->statusBar()->showMessage(QString("%1 cannot evaluate %2; choose another mode")
                                     .arg(render::ShadingModeLabel(spec.mode))
                                     .arg(ReflectanceModelName(spec.material.model)));
    return;
  }
  if (backend != spec.backend)
  {
    // Another backend is another panel: rebuild the comparison.
    std::vector<widgets::PanelSpec> specs;
    for (int i = 0; i < this->View->PanelCount(); ++i)
    {
      specs.push_back(i == index ? spec : this->View->Panel(i)->Spec());
    }
    specs[index].backend = backend;
    this->Current.panels = specs;
    this->View->SetPanels(specs);
    this->View->SetProfileLine(this->View->GetProfileLine());
    this->View->SetCurrentPanel(index);
    this->View->RenderAll();
    return;
  }
  this->View->SetPanelSpec(index, spec);
  this->Current.panels[index] = this->View->Panel(index)->Spec();
  this->statusBar()->showMessage(QString("panel %1 re-rendered in %2 ms")
                                   .arg(index + 1)
                                   .arg(this->View->Panel(index)->LastRenderMilliseconds(), 0,
                                     'f', 1));
}

void MainWindow::UpdatePlot()
{
  switch (this->Current.plot)
  {
    case PlotKind::Profile:
    {
      std::vector<widgets::ProfileCurve> curves;
      const std::vector<int> panels = this->View->ProfilePanels();
      const std::vector<widgets::Profile> profiles = this->View->Profiles();
      for (size_t i = 0; i < panels.size(); ++i)
      {
        // The legend names a curve by its title up to a colon.
        const std::string& title = this->View->Panel(panels[i])->Spec().title;
        curves.push_back({ title.substr(0, title.find(':')),
          widgets::PanelColor(panels[i]), profiles[i] });
      }
      this->ProfileChart->SetCurves(curves);
      break;
    }
    case PlotKind::Parameter:
    {
      std::vector<widgets::ParameterSeries> series;
      int color = 0;
      for (const Study::Series& s : this->CurrentStudy.series)
      {
        series.push_back({ QString::fromStdString(s.name), widgets::PanelColor(color++), s.x, s.y });
      }
      std::vector<QString> categories;
      for (const std::string& c : this->CurrentStudy.categories)
      {
        categories.push_back(QString::fromStdString(c));
      }
      this->ParameterChart->SetSeries(QString::fromStdString(this->CurrentStudy.title),
        QString::fromStdString(this->CurrentStudy.xTitle),
        QString::fromStdString(this->CurrentStudy.yTitle), series, this->CurrentStudy.marker,
        categories, QString::fromStdString(this->CurrentStudy.markerLabel));
      break;
    }
    case PlotKind::Brdf:
    case PlotKind::Scanline:
    case PlotKind::None:
      break;
  }
}

void MainWindow::UpdateBrdfPlot()
{
  this->BrdfChart->SetLobes(
    widgets::DefaultLobes(this->Shininess->value(), this->Roughness->value() / 100.0),
    this->ThetaL->value());
}

void MainWindow::RefreshNow()
{
  this->View->RenderAll();
  QApplication::processEvents();
  this->PlotTimer->stop();
  this->UpdatePlot();
  if (this->Current.plot == PlotKind::Brdf)
  {
    this->UpdateBrdfPlot();
  }
  QApplication::processEvents();
}

std::string MainWindow::PlotCsv() const
{
  if (this->Current.plot == PlotKind::Profile)
  {
    return this->ProfileChart->ToCsv();
  }
  std::ostringstream csv;
  csv.precision(8);
  if (this->Current.plot == PlotKind::Parameter)
  {
    csv << "series,x,y\n";
    for (const Study::Series& s : this->CurrentStudy.series)
    {
      for (size_t i = 0; i < s.x.size(); ++i)
      {
        csv << '"' << s.name << "\"," << s.x[i] << ',' << s.y[i] << '\n';
      }
    }
    return csv.str();
  }
  if (this->Current.plot == PlotKind::Scanline)
  {
    return this->Inspector->ToCsv();
  }
  if (this->Current.plot == PlotKind::Brdf)
  {
    csv << "lobe,theta_l,theta_v,f_r\n";
    for (const widgets::BrdfLobe& lobe :
      widgets::DefaultLobes(this->Shininess->value(), this->Roughness->value() / 100.0))
    {
      for (int v = -90; v <= 90; ++v)
      {
        csv << '"' << lobe.name << "\"," << this->ThetaL->value() << ',' << v << ','
            << widgets::BrdfInPlane(lobe.material, this->ThetaL->value(), v) << '\n';
      }
    }
  }
  return csv.str();
}

void MainWindow::dragEnterEvent(QDragEnterEvent* event)
{
  if (event->mimeData()->hasUrls())
  {
    event->acceptProposedAction();
  }
}

void MainWindow::dropEvent(QDropEvent* event)
{
  const QList<QUrl> urls = event->mimeData()->urls();
  if (urls.isEmpty())
  {
    return;
  }
  std::string error;
  if (!this->OpenMesh(urls.front().toLocalFile().toStdString(), error))
  {
    QMessageBox::warning(this, "ShadingLab", QString::fromStdString(error));
  }
}

void MainWindow::ListArrays()
{
  const QString kept = this->ColorBy->currentData().toString();
  this->ColorBy->clear();
  this->ColorBy->addItem("None (the material's colour)", QString());
  vtkPolyData* mesh =
    this->View->PanelCount() > 0 ? this->View->Panel(0)->Spec().mesh.GetPointer() : nullptr;
  // The arrays a scientist colours by: not the normals or ids the
  // preparation added.
  auto listed = [](const char* name) {
    return name && std::strcmp(name, "Normals") != 0 && std::strcmp(name, "ExactNormal") != 0 &&
      std::strcmp(name, "OriginalPointIds") != 0 && std::strcmp(name, "vtkOriginalPointIds") != 0;
  };
  for (int a = 0; mesh && a < mesh->GetPointData()->GetNumberOfArrays(); ++a)
  {
    if (const char* name = mesh->GetPointData()->GetArrayName(a); listed(name))
    {
      this->ColorBy->addItem(name, QString("POINTS:") + name);
    }
  }
  for (int a = 0; mesh && a < mesh->GetCellData()->GetNumberOfArrays(); ++a)
  {
    if (const char* name = mesh->GetCellData()->GetArrayName(a); listed(name))
    {
      this->ColorBy->addItem(QString("%1 (cells)").arg(name), QString("CELLS:") + name);
    }
  }
  const int again = this->ColorBy->findData(kept);
  this->ColorBy->setCurrentIndex(std::max(0, again));
  this->ApplyColorBy();
}

std::string MainWindow::ApplyColorBy(const std::string& colorBy)
{
  if (!colorBy.empty())
  {
    const int index = this->ColorBy->findData(QString::fromStdString(colorBy));
    if (index < 0)
    {
      const std::string error = "no array '" + colorBy + "' in this scene's mesh";
      this->statusBar()->showMessage(QString::fromStdString(error));
      return error;
    }
    this->ColorBy->setCurrentIndex(index);
  }
  const std::string spec = this->ColorBy->currentData().toString().toStdString();
  const std::string map = this->ColorMapChoice->currentText().toStdString();
  const std::string error = this->View->SetColorBy(spec, map);
  if (!error.empty())
  {
    this->statusBar()->showMessage(QString::fromStdString(error));
    return error;
  }
  const widgets::ViewState& view = this->View->View();
  this->Legend->SetMap(spec.empty() ? nullptr : &view.colorMap, this->ColorBy->currentText().toStdString());
  return {};
}

} // namespace shadinglab::gui
